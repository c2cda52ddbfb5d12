/* fuzz_input.h - give a fuzzer's bytes to a reader that takes a file name.
 *
 * The parsers under test read files (swr_params_load, sww_regime_load): the
 * bytes go to an anonymous in-memory file (memfd_create) and the reader gets
 * its /proc/self/fd path, so no file is left anywhere and no disk is touched. */
#ifndef FUZZ_INPUT_H
#define FUZZ_INPUT_H

#ifndef _GNU_SOURCE
#define _GNU_SOURCE
#endif
#include <stdio.h>
#include <stdlib.h>
#include <sys/mman.h>
#include <unistd.h>

/* Path of an in-memory file holding data[0..n); its descriptor in *fd (close
 * it when done). NULL when the file cannot be made. */
static inline const char *fuzz_file(const unsigned char *data, size_t n, int *fd, char *path,
                                    size_t len)
{
    *fd = memfd_create("fuzz", 0);
    if (*fd < 0)
        return NULL;
    size_t off = 0;
    while (off < n) {
        const ssize_t w = write(*fd, data + off, n - off);
        if (w <= 0) {
            close(*fd);
            return NULL;
        }
        off += (size_t)w;
    }
    snprintf(path, len, "/proc/self/fd/%d", *fd);
    return path;
}

#endif
