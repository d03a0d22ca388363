/* POSIX and HDF5 C-API services that Fortran cannot reach portably: signal handlers
 * (a handler must only set a volatile sig_atomic_t), fsync, flock, the identity of two
 * paths, a random token for temporary names, and three HDF5 settings that the HDF5
 * Fortran API of Debian's 1.10 does not offer (metadata-cache configuration, SWMR write
 * and read, the error stack as text). Every function returns 0 or an errno value (or a
 * negative value for an HDF5 failure) and never prints; the Fortran side turns that into
 * a message (src/vibrobeam_filesystem.f90, src/vibrobeam_signals.f90,
 * src/vibrobeam_hdf5.f90). */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <hdf5.h>

/* ---------------------------------------------------------------------------------
 * Signals */

/* The signal that asked the run to stop (SIGINT or SIGTERM), 0 while none did. */
static volatile sig_atomic_t interrupt_signal = 0;

/* First SIGINT/SIGTERM: remember it and give both signals back their default action,
 * so a second one ends the process at once (async-signal-safe: sigaction only). */
static void on_interrupt(int signal_number)
{
    struct sigaction default_action;
    memset(&default_action, 0, sizeof default_action);
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    interrupt_signal = signal_number;
    sigaction(SIGINT, &default_action, NULL);
    sigaction(SIGTERM, &default_action, NULL);
}

int vb_install_interrupt_handlers(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    /* SA_RESTART: a system call interrupted by the first signal resumes (an fsync or a
     * write in progress completes), the loop then sees the flag. */
    action.sa_flags = SA_RESTART;
    if (sigaction(SIGINT, &action, NULL) != 0) return errno;
    if (sigaction(SIGTERM, &action, NULL) != 0) return errno;
    return 0;
}

int vb_interrupt_signal(void) { return (int)interrupt_signal; }

/* SIGXFSZ (a write beyond `ulimit -f`) kills the process by default, and libgfortran
 * installs a backtrace handler for it; ignored, the write fails with EFBIG instead and
 * is reported like any other I/O error. */
int vb_ignore_file_size_signal(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = SIG_IGN;
    sigemptyset(&action.sa_mask);
    if (sigaction(SIGXFSZ, &action, NULL) != 0) return errno;
    return 0;
}

/* ---------------------------------------------------------------------------------
 * Files and directories */

/* fsync(2) the file or directory `path` (opened read-only: fsync acts on the inode). */
int vb_fsync_path(const char *path)
{
    int fd = open(path, O_RDONLY | O_CLOEXEC);
    int error;
    if (fd < 0) return errno;
    error = fsync(fd) != 0 ? errno : 0;
    /* EINVAL: a file system without fsync for directories; nothing to wait for. */
    if (error == EINVAL) error = 0;
    if (close(fd) != 0 && error == 0) error = errno;
    return error;
}

/* Exclusive flock(2) on the directory `path`, waiting for other holders; `*fd` keeps the
 * lock until vb_unlock. */
int vb_lock(const char *path, int *fd)
{
    *fd = open(path, O_RDONLY | O_CLOEXEC);
    if (*fd < 0) return errno;
    while (flock(*fd, LOCK_EX) != 0) {
        if (errno == EINTR) continue;
        int error = errno;
        close(*fd);
        *fd = -1;
        return error;
    }
    return 0;
}

int vb_unlock(int fd)
{
    if (fd < 0) return 0;
    if (close(fd) != 0) return errno; /* closing the descriptor releases the lock */
    return 0;
}

long vb_process_id(void) { return (long)getpid(); }

/* 64 random bits (getrandom), or the monotonic clock's nanoseconds when the kernel has
 * no entropy to give without blocking. */
uint64_t vb_random_token(void)
{
    uint64_t token = 0;
    if (getrandom(&token, sizeof token, GRND_NONBLOCK) != (ssize_t)sizeof token) {
        struct timespec now;
        clock_gettime(CLOCK_MONOTONIC, &now);
        token = (uint64_t)now.tv_sec * 1000000000u + (uint64_t)now.tv_nsec;
    }
    return token;
}

/* The current UTC time as 'YYYYMMDDTHHMMSSZ' (17 bytes with the NUL). */
int vb_utc_stamp(char *buffer, int length)
{
    time_t now = time(NULL);
    struct tm parts;
    if (length < 17 || gmtime_r(&now, &parts) == NULL) return EINVAL;
    strftime(buffer, (size_t)length, "%Y%m%dT%H%M%SZ", &parts);
    return 0;
}

/* Peak resident set size of this process in kB (getrusage). */
long vb_peak_rss_kb(void)
{
    struct rusage usage;
    if (getrusage(RUSAGE_SELF, &usage) != 0) return -1;
    return usage.ru_maxrss;
}

/* ---------------------------------------------------------------------------------
 * Text files. libgfortran (12) does not report a failed write of its buffer (a full
 * disk, `ulimit -f`) to a formatted WRITE, FLUSH or CLOSE with iostat: the file is
 * silently truncated. Text results are therefore written here, every write(2) checked;
 * Fortran formats each line into a string first. */

struct text_file {
    int fd;
    size_t used;
    char buffer[1 << 16];
};

/* Write out the buffer; 0 or errno. */
static int text_drain(struct text_file *file)
{
    size_t done = 0;
    while (done < file->used) {
        ssize_t written = write(file->fd, file->buffer + done, file->used - done);
        if (written < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        done += (size_t)written;
    }
    file->used = 0;
    return 0;
}

/* Create `path` (it must not exist) for writing; NULL with *error = errno on failure. */
void *vb_text_open(const char *path, int *error)
{
    struct text_file *file = malloc(sizeof *file);
    *error = 0;
    if (file == NULL) {
        *error = ENOMEM;
        return NULL;
    }
    file->fd = open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (file->fd < 0) {
        *error = errno;
        free(file);
        return NULL;
    }
    file->used = 0;
    return file;
}

/* Append `length` bytes; 0 or errno. */
int vb_text_write(void *handle, const char *data, size_t length)
{
    struct text_file *file = handle;
    while (length > 0) {
        size_t room = sizeof file->buffer - file->used, part = length < room ? length : room;
        memcpy(file->buffer + file->used, data, part);
        file->used += part;
        data += part;
        length -= part;
        if (file->used == sizeof file->buffer) {
            int error = text_drain(file);
            if (error != 0) return error;
        }
    }
    return 0;
}

/* Append one line of `count` numbers, each right-aligned in `width` characters: in
 * scientific notation with `digits` digits after the point (C's %E: a 3-digit exponent
 * keeps its E, which Fortran's ES edit drops), the last `integers` of them as integers
 * (counts, flags); then a newline. 0 or errno. */
int vb_text_write_row(void *handle, const double *values, int count, int width, int digits, int integers)
{
    char field[64];
    int k;
    for (k = 0; k < count; ++k) {
        int length = k < count - integers
                         ? snprintf(field, sizeof field, "%*.*E", width, digits, values[k])
                         : snprintf(field, sizeof field, "%*lld", width, (long long)values[k]);
        int error = vb_text_write(handle, field, (size_t)length);
        if (error != 0) return error;
    }
    return vb_text_write(handle, "\n", 1);
}

/* Write out, fsync and close; frees the handle; 0 or the first errno. */
int vb_text_close(void *handle)
{
    struct text_file *file = handle;
    int error = text_drain(file);
    if (error == 0 && fsync(file->fd) != 0) error = errno;
    if (close(file->fd) != 0 && error == 0) error = errno;
    free(file);
    return error;
}

/* Close without writing out what is buffered; frees the handle. */
void vb_text_abandon(void *handle)
{
    struct text_file *file = handle;
    if (file == NULL) return;
    close(file->fd);
    free(file);
}

/* End the process with `status` at once: stdio flushed, no atexit handlers. HDF5's own
 * exit handler would try again to write a file whose every write fails (a full disk)
 * and can crash doing so; by then every result file has been closed or discarded. */
void vb_exit(int status)
{
    fflush(NULL);
    _exit(status);
}

/* ---------------------------------------------------------------------------------
 * HDF5 */

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
 * of a writer that was killed (its superblock still says "open for SWMR write"). */
hid_t vb_h5_open_read(const char *name, int swmr)
{
    unsigned flags = H5F_ACC_RDONLY;
    if (swmr) flags |= H5F_ACC_SWMR_READ;
    return H5Fopen(name, flags, H5P_DEFAULT);
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
