/* Questions about paths that the input checks ask before a run writes anything
 * (vibrobeam_output_target.f90): what kind of entry a path names, whether two paths name
 * the same file, the canonical form of a path, and the free space of a file system.
 *
 * In C because the answers live in struct stat and struct statvfs, whose layout differs
 * between C libraries and architectures; Fortran calls these through bind(C). Every
 * function returns a status and never exits. */
#define _XOPEN_SOURCE 700
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/statvfs.h>

/* 0: nothing there (or not reachable), 1: regular file, 2: directory, 3: anything else. */
int vibrobeam_path_kind(const char *path)
{
    struct stat info;
    if (stat(path, &info) != 0) return 0;
    if (S_ISREG(info.st_mode)) return 1;
    if (S_ISDIR(info.st_mode)) return 2;
    return 3;
}

/* 1 when both paths name the same file (same device and inode: symbolic and hard links
 * included), 0 when they do not or one of them does not exist. */
int vibrobeam_same_file(const char *first, const char *second)
{
    struct stat a, b;
    if (stat(first, &a) != 0 || stat(second, &b) != 0) return 0;
    return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

/* The canonical absolute path of an existing path (realpath(3)) in `resolved`, of
 * `size` bytes. 0 on success, -1 when the path cannot be resolved or does not fit. */
int vibrobeam_real_path(const char *path, char *resolved, size_t size)
{
    char *full = realpath(path, NULL);
    if (full == NULL) return -1;
    if (strlen(full) + 1 > size) {
        free(full);
        return -1;
    }
    strcpy(resolved, full);
    free(full);
    return 0;
}

/* Bytes available to an unprivileged user on the file system holding `path`, and its
 * size (statvfs(3): f_bavail and f_blocks blocks of f_frsize bytes; a size of 0 is a
 * file system without storage, such as /proc or /sys). 0 on success, -1 on failure. */
int vibrobeam_free_bytes(const char *path, double *bytes, double *size)
{
    struct statvfs info;
    if (statvfs(path, &info) != 0) return -1;
    *bytes = (double)info.f_bavail * (double)info.f_frsize;
    *size = (double)info.f_blocks * (double)info.f_frsize;
    return 0;
}
