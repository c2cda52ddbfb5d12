/* fuzz_config.c - libFuzzer target: snowregime's --config reader.
 *
 * Any bytes as a config file: swr_params_load must return 0 or -1 with a
 * one-line message (no crash, no sanitizer report, no hang); a file that loads
 * must give parameters that swr_params_validate accepts or rejects cleanly and
 * that print. Built by tests/fuzz/run.sh (clang, -fsanitize=fuzzer); the same
 * entry point runs over the corpus in every test build (fuzz_replay.c). */
#include "fuzz_input.h"   /* first: it defines _GNU_SOURCE for memfd_create */
#include <stdint.h>
#include <string.h>

#include "swr_params.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[64], err[400];
    int fd;
    if (!fuzz_file(data, size, &fd, path, sizeof path))
        return 0;
    swr_params p;
    swr_params_default(&p);
    const int rc = swr_params_load(&p, path, err, sizeof err);
    close(fd);
    if (rc != 0) {
        if (!memchr(err, '\0', sizeof err) || strchr(err, '\n'))
            __builtin_trap(); /* one terminated line */
        return 0;
    }
    if (swr_params_validate(&p, err, sizeof err) == 0) {
        FILE *f = fopen("/dev/null", "w");
        if (f) {
            swr_params_print(&p, "# ", f);
            fclose(f);
        }
    }
    return 0;
}
