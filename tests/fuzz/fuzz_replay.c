/* fuzz_replay.c - run a libFuzzer target's entry point over files, without
 * libFuzzer: every file (or every file in every folder) given on the command
 * line once. Linked with each fuzz_*.c into the normal test build, so ctest
 * replays the seed corpus and every reproducer under the sanitizers.
 * Exit 0 when every input ran, 1 when an input could not be read. */
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int run_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "fuzz_replay: cannot read %s\n", path);
        return 1;
    }
    unsigned char *buf = malloc(1 << 20);
    const size_t n = buf ? fread(buf, 1, 1 << 20, f) : 0;
    fclose(f);
    if (!buf)
        return 1;
    LLVMFuzzerTestOneInput(buf, n);
    free(buf);
    return 0;
}

int main(int argc, char **argv)
{
    int bad = 0, runs = 0;
    for (int a = 1; a < argc; a++) {
        struct stat st;
        if (stat(argv[a], &st) == 0 && S_ISDIR(st.st_mode)) {
            DIR *d = opendir(argv[a]);
            struct dirent *e;
            while (d && (e = readdir(d))) {
                if (e->d_name[0] == '.')
                    continue;
                char p[4096];
                snprintf(p, sizeof p, "%s/%s", argv[a], e->d_name);
                bad |= run_file(p);
                runs++;
            }
            if (d)
                closedir(d);
        } else {
            bad |= run_file(argv[a]);
            runs++;
        }
    }
    printf("fuzz_replay: %d inputs\n", runs);
    return bad;
}
