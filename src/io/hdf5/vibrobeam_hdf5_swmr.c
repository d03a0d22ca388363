/* Three HDF5 settings that the HDF5 Fortran API of Debian's 1.10 does not offer, for
 * src/io/hdf5/vibrobeam_hdf5_base.f90 and its users: metadata-cache configuration, SWMR write and
 * read, the error stack as text. Every function returns 0 or a negative value for an
 * HDF5 failure and never prints. */
#include <errno.h>
#include <stdio.h>
#include <string.h>

#include <hdf5.h>

/* Keep the metadata cache from writing dirty entries between two H5Fflush calls: no
 * evictions, and a fixed size (automatic resizing requires evictions). Between flushes
 * the file on disk then stays as the last flush left it. */
int vb_h5_disable_evictions(hid_t file_access_list)
{
    H5AC_cache_config_t config;
    memset(&config, 0, sizeof config);
    config.version = H5AC__CURR_CACHE_CONFIG_VERSION;
    if (H5Pget_mdc_config(file_access_list, &config) < 0) return -1;
    config.evictions_enabled = 0;
    config.incr_mode = H5C_incr__off;
    config.flash_incr_mode = H5C_flash_incr__off;
    config.decr_mode = H5C_decr__off;
    if (H5Pset_mdc_config(file_access_list, &config) < 0) return -1;
    return 0;
}

/* Switch an open file (libver latest, every object created) to SWMR write mode: HDF5
 * then orders its metadata writes so that a reader - or a reader after a crash - always
 * finds a consistent file. */
int vb_h5_start_swmr_write(hid_t file)
{
    return H5Fstart_swmr_write(file) < 0 ? -1 : 0;
}

/* Open `name` read-only; with `swmr` /= 0 as a SWMR reader, which also opens the file
 * of a writer that was killed (its superblock still says "open for SWMR write"). With
 * `locking` = 0 the reader takes no file lock: it then never stands in the way of a
 * writer that is running (the lock a reader holds, even for an instant, would make the
 * writer's create of a new file fail). */
hid_t vb_h5_open_read(const char *name, int swmr, int locking)
{
    unsigned flags = H5F_ACC_RDONLY;
    hid_t access, file;
    if (swmr) flags |= H5F_ACC_SWMR_READ;
    if (locking) return H5Fopen(name, flags, H5P_DEFAULT);
    access = H5Pcreate(H5P_FILE_ACCESS);
    if (access < 0) return -1;
    if (H5Pset_file_locking(access, 0, 1) < 0) {
        H5Pclose(access);
        return -1;
    }
    file = H5Fopen(name, flags, access);
    H5Pclose(access);
    return file;
}

/* Walk callback: keep the innermost entry's description, and the C library's reason
 * when an entry carries one ("..., error message = 'No space left on device', ..."). */
struct error_text {
    char *buffer;
    int length;
    int have_reason;
};

static herr_t keep_description(unsigned depth, const H5E_error2_t *entry, void *data)
{
    struct error_text *text = data;
    const char *reason, *end;
    (void)depth;
    if (entry->desc == NULL || text->have_reason) return 0;
    reason = strstr(entry->desc, "error message = '");
    if (reason != NULL) {
        reason += strlen("error message = '");
        end = strchr(reason, '\'');
        if (end != NULL && end - reason < text->length) {
            memcpy(text->buffer, reason, (size_t)(end - reason));
            text->buffer[end - reason] = '\0';
            text->have_reason = 1;
            return 0;
        }
    }
    if (text->buffer[0] == '\0') snprintf(text->buffer, (size_t)text->length, "%s", entry->desc);
    return 0;
}

/* The reason of the last HDF5 failure as text (the errno text when the error stack holds
 * one, else the innermost description); '' when the stack is empty. Clears the stack. */
int vb_h5_error_text(char *buffer, int length)
{
    struct error_text text = {buffer, length, 0};
    if (length < 1) return EINVAL;
    buffer[0] = '\0';
    H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, keep_description, &text);
    H5Eclear2(H5E_DEFAULT);
    return 0;
}
