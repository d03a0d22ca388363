/* Files and the process's identity, for src/os/vibrobeam_filesystem.f90 and
 * src/io/vibrobeam_text_file.f90: fsync, flock, links, directory listings, a random token and a UTC stamp for temporary names, the peak
 * resident set size, and text files whose every write(2) is checked. Every function
 * returns 0 or an errno value and never prints; the Fortran side turns that into a
 * message. */
#define _GNU_SOURCE
#include <errno.h>
#include <fcntl.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/file.h>
#include <sys/random.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

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

/* Exclusive flock(2) on the existing file or directory `path` without waiting: -1 when
 * another open file description holds it (another process), else 0 or errno; `*fd` keeps
 * the lock until vb_unlock. */
int vb_try_lock(const char *path, int *fd)
{
    *fd = open(path, O_RDONLY | O_CLOEXEC);
    if (*fd < 0) return errno;
    while (flock(*fd, LOCK_EX | LOCK_NB) != 0) {
        if (errno == EINTR) continue;
        int error = errno;
        close(*fd);
        *fd = -1;
        return error == EWOULDBLOCK ? -1 : error;
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

/* Create the empty file `path` when it does not exist (an existing one is kept). */
int vb_touch(const char *path)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_CLOEXEC, 0666);
    if (fd < 0) return errno;
    if (close(fd) != 0) return errno;
    return 0;
}

/* A second name `to` (which must not exist) for the file `from` (link(2)). */
int vb_link(const char *from, const char *to) { return link(from, to) != 0 ? errno : 0; }

/* Remove the empty directory `path`. */
int vb_remove_directory(const char *path) { return rmdir(path) != 0 ? errno : 0; }

/* The entries of a directory, one name at a time ("." and ".." left out). */
void *vb_directory_open(const char *path, int *error)
{
    DIR *directory = opendir(path);
    *error = directory == NULL ? errno : 0;
    return directory;
}

/* The next name into `buffer` (not NUL-terminated); its length, 0 at the end, -1 when it
 * is longer than `length`. */
int vb_directory_next(void *handle, char *buffer, int length)
{
    struct dirent *entry;
    size_t size;
    do {
        entry = readdir((DIR *)handle);
        if (entry == NULL) return 0;
    } while (strcmp(entry->d_name, ".") == 0 || strcmp(entry->d_name, "..") == 0);
    size = strlen(entry->d_name);
    if (size > (size_t)length) return -1;
    memcpy(buffer, entry->d_name, size);
    return (int)size;
}

void vb_directory_close(void *handle)
{
    if (handle != NULL) closedir((DIR *)handle);
}

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
