/* test_swo.c - the common output writer (common/swo_out.h): the output-folder
 * contract, whole-or-nothing files, refusal of non-regular final names, write
 * errors on a real full disk, the signal clean-up, and the comma-list rule. */
#define _GNU_SOURCE   /* setgroups, mount */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <grp.h>
#include <setjmp.h>
#include <signal.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>
#include <cmocka.h>

#include "swo_out.h"
#include "swo_err.h"

static char g_base[] = "/tmp/test_swo_XXXXXX";

static int setup(void **s)
{
    (void)s;
    if (!mkdtemp(g_base))
        return -1;
    chmod(g_base, 0755);   /* the unprivileged check reaches into it */
    return 0;
}

/* rm -r of the test's own folder (only paths under g_base) */
static void rm_tree(const char *p)
{
    struct stat st;
    if (lstat(p, &st) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        DIR *d = opendir(p);
        if (d) {
            struct dirent *e;
            while ((e = readdir(d)) != NULL) {
                if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
                    continue;
                char q[600];
                snprintf(q, sizeof q, "%s/%s", p, e->d_name);
                rm_tree(q);
            }
            closedir(d);
        }
        rmdir(p);
    } else {
        unlink(p);
    }
}

static int teardown(void **s)
{
    (void)s;
    rm_tree(g_base);
    return 0;
}

static char *path(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
static char *path(const char *fmt, ...)
{
    static char buf[8][600];
    static int k;
    char rel[400];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rel, sizeof rel, fmt, ap);
    va_end(ap);
    k = (k + 1) % 8;
    snprintf(buf[k], sizeof buf[k], "%s/%s", g_base, rel);
    return buf[k];
}

static void put(const char *p, const char *text)
{
    FILE *f = fopen(p, "w");
    assert_non_null(f);
    fputs(text, f);
    assert_int_equal(fclose(f), 0);
}

static int is_file_with(const char *p, const char *text)
{
    char buf[256] = "";
    FILE *f = fopen(p, "r");
    if (!f)
        return 0;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    return strcmp(buf, text) == 0;
}

/* entries of a folder other than . and .. */
static int entries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return -1;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        n += strcmp(e->d_name, ".") && strcmp(e->d_name, "..");
    closedir(d);
    return n;
}

static int temporaries(const char *dir)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0;
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        n += strncmp(e->d_name, ".tmp-", 5) == 0;
    closedir(d);
    return n;
}

static int write_set(const char *dir, int force, const char *name, const char *text, char *err,
                     size_t errlen)
{
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", dir, force, 1 };
    int rc = swo_alloc(&spec, &o, err, errlen);
    if (rc != SWO_OK)
        return rc;
    FILE *f = swo_open(o, name, err, errlen);
    if (!f) {
        rc = swo_code(o);
        swo_free(o);
        return rc;
    }
    fputs(text, f);
    rc = swo_commit(o, err, errlen);
    swo_free(o);
    return rc;
}

static int has_marker(const char *dir)
{
    char p[600], line[200];
    snprintf(p, sizeof p, "%s/%s", dir, SWO_MARKER);
    FILE *f = fopen(p, "r");
    if (!f)
        return 0;
    int ok = fgets(line, sizeof line, f) && !strcmp(line, "SnowWall output folder\n")
             && fgets(line, sizeof line, f) && !strcmp(line, "tool: test_swo\n")
             && fgets(line, sizeof line, f) && !strncmp(line, "written: 20", 11)
             && line[strlen(line) - 2] == 'Z';
    fclose(f);
    return ok;
}

static void new_folder_gets_marker_and_abort_removes_it(void **s)
{
    (void)s;
    char err[600];
    /* abort: temporaries and the folders the set created are gone */
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", path("new/a/b"), 0, 1 };
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    FILE *f = swo_open(o, "x.csv", err, sizeof err);
    assert_non_null(f);
    fputs("1,2\n", f);
    assert_int_equal(temporaries(path("new/a/b")), 1);
    swo_abort(o);
    swo_free(o);
    assert_int_equal(access(path("new"), F_OK), -1);
    /* commit: the file and the marker, nothing else */
    assert_int_equal(write_set(path("new/a/b"), 0, "x.csv", "1,2\n", err, sizeof err), SWO_OK);
    assert_true(is_file_with(path("new/a/b/x.csv"), "1,2\n"));
    assert_true(has_marker(path("new/a/b")));
    assert_int_equal(entries(path("new/a/b")), 2);
    /* without parents, a missing parent is refused */
    const swo_spec np = { "test_swo", "--out", path("nope/x"), 0, 0 };
    assert_int_equal(swo_alloc(&np, &o, err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "parent folder does not exist"));
    assert_int_equal(access(path("nope"), F_OK), -1);
}

static void empty_and_own_folders_are_written(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("empty"), 0755), 0);
    assert_int_equal(write_set(path("empty"), 0, "a.csv", "A\n", err, sizeof err), SWO_OK);
    assert_true(has_marker(path("empty")));
    /* own folder: a foreign file beside the marker is left alone; a.csv replaced */
    put(path("empty/notes.txt"), "mine\n");
    assert_int_equal(write_set(path("empty"), 0, "a.csv", "B\n", err, sizeof err), SWO_OK);
    assert_true(is_file_with(path("empty/a.csv"), "B\n"));
    assert_true(is_file_with(path("empty/notes.txt"), "mine\n"));
    assert_int_equal(entries(path("empty")), 3);
    /* a marker that is not a regular file does not make the folder the tool's */
    assert_int_equal(mkdir(path("fake"), 0755), 0);
    assert_int_equal(mkdir(path("fake/%s", SWO_MARKER), 0755), 0);
    assert_int_equal(write_set(path("fake"), 0, "a.csv", "A\n", err, sizeof err), SWO_EREFUSED);
}

static void foreign_folder_refused_unless_force(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("foreign"), 0755), 0);
    put(path("foreign/notes.txt"), "keep\n");
    put(path("foreign/a.csv"), "old\n");
    assert_int_equal(write_set(path("foreign"), 0, "a.csv", "new\n", err, sizeof err),
                     SWO_EREFUSED);
    char want[700];
    snprintf(want, sizeof want, "--out: '%s' is not empty and not a SnowWall output folder "
             "(holds 'a.csv'); give --force to write into it", path("foreign"));
    assert_string_equal(err, want);
    assert_true(is_file_with(path("foreign/a.csv"), "old\n"));
    assert_int_equal(entries(path("foreign")), 2);
    /* --force: its own name replaced, the foreign file intact, no marker added */
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", path("foreign"), 1, 1 };
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    assert_non_null(swo_note(o));
    assert_non_null(strstr(swo_note(o), "--force"));
    FILE *f = swo_open(o, "a.csv", err, sizeof err);
    assert_non_null(f);
    fputs("new\n", f);
    assert_int_equal(swo_commit(o, err, sizeof err), SWO_OK);
    swo_free(o);
    assert_true(is_file_with(path("foreign/a.csv"), "new\n"));
    assert_true(is_file_with(path("foreign/notes.txt"), "keep\n"));
    assert_int_equal(entries(path("foreign")), 2);
}

static void linked_or_non_folder_out_refused(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("target"), 0755), 0);
    assert_int_equal(symlink(path("target"), path("link")), 0);
    assert_int_equal(write_set(path("link"), 0, "a.csv", "x\n", err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "is a symbolic link"));
    /* "link/" names the link's target: still the link that is refused */
    char slash[700];
    snprintf(slash, sizeof slash, "%s/", path("link"));
    assert_int_equal(write_set(slash, 0, "a.csv", "x\n", err, sizeof err), SWO_EREFUSED);
    assert_int_equal(entries(path("target")), 0);
    put(path("plain"), "p\n");
    assert_int_equal(write_set(path("plain"), 0, "a.csv", "x\n", err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "exists and is not a folder"));
    assert_true(is_file_with(path("plain"), "p\n"));
}

static void non_regular_final_names_refused_and_left(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("nr"), 0755), 0);
    assert_int_equal(write_set(path("nr"), 0, "first.csv", "1\n", err, sizeof err), SWO_OK);
    /* a FIFO (opening it would block), a folder, a link to a file */
    assert_int_equal(mkfifo(path("nr/fifo.csv"), 0644), 0);
    assert_int_equal(mkdir(path("nr/dir.csv"), 0755), 0);
    put(path("victim"), "v\n");
    assert_int_equal(symlink(path("victim"), path("nr/link.csv")), 0);
    const char *names[] = { "fifo.csv", "dir.csv", "link.csv" };
    const char *kinds[] = { "a FIFO", "a folder", "a symbolic link" };
    for (int k = 0; k < 3; k++) {
        assert_int_equal(write_set(path("nr"), 0, names[k], "x\n", err, sizeof err), SWO_EREFUSED);
        assert_non_null(strstr(err, kinds[k]));
        assert_non_null(strstr(err, names[k]));
    }
    struct stat st;
    assert_int_equal(lstat(path("nr/fifo.csv"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(lstat(path("nr/dir.csv"), &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(lstat(path("nr/link.csv"), &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    assert_true(is_file_with(path("victim"), "v\n"));
    assert_int_equal(temporaries(path("nr")), 0);
    /* a FIFO that appears after the file was registered: refused at commit,
     * before any rename, every temporary removed */
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", path("nr"), 0, 1 };
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    FILE *f1 = swo_open(o, "first.csv", err, sizeof err), *f2 = swo_open(o, "late.csv", err, sizeof err);
    assert_non_null(f1);
    assert_non_null(f2);
    fputs("2\n", f1);
    fputs("late\n", f2);
    assert_int_equal(mkfifo(path("nr/late.csv"), 0644), 0);
    assert_int_equal(swo_commit(o, err, sizeof err), SWO_EREFUSED);
    swo_free(o);
    assert_true(is_file_with(path("nr/first.csv"), "1\n"));
    assert_int_equal(lstat(path("nr/late.csv"), &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(temporaries(path("nr")), 0);
}

static void device_node_refused_and_left(void **s)
{
    (void)s;
    char err[600];
    /* a /dev/full-like node made for the test (never a system node) */
    assert_int_equal(mkdir(path("dev"), 0755), 0);
    if (mknod(path("dev/full.csv"), S_IFCHR | 0666, makedev(1, 7)) != 0)
        skip();   /* no CAP_MKNOD here */
    /* in a folder */
    assert_int_equal(write_set(path("dev"), 1, "full.csv", "x\n", err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "a character device"));
    /* as a file of its own (--out FILE) */
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", NULL, 0, 0 };
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    assert_int_equal(swo_check(o, path("dev/full.csv"), err, sizeof err), SWO_EREFUSED);
    assert_null(swo_open(o, path("dev/full.csv"), err, sizeof err));
    assert_int_equal(swo_code(o), SWO_EREFUSED);
    swo_free(o);
    struct stat st;
    assert_int_equal(lstat(path("dev/full.csv"), &st), 0);
    assert_true(S_ISCHR(st.st_mode));
    assert_int_equal(major(st.st_rdev), 1);
    assert_int_equal(minor(st.st_rdev), 7);
    assert_int_equal(temporaries(path("dev")), 0);
}

static void files_by_path_whole_or_nothing(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("files"), 0755), 0);
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--trace-csv", NULL, 0, 0 };
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    FILE *f = swo_open(o, path("files/t.csv"), err, sizeof err);
    assert_non_null(f);
    fputs("t\n", f);
    /* a file registered for a writer of its own that never wrote it fails the
     * commit: nothing renamed, nothing left */
    assert_non_null(swo_add(o, path("files/never.png"), err, sizeof err));
    assert_int_equal(swo_commit(o, err, sizeof err), SWO_EFAIL);
    assert_non_null(strstr(err, "never.png"));
    swo_free(o);
    assert_int_equal(entries(path("files")), 0);
    /* a missing folder is named */
    assert_int_equal(swo_alloc(&spec, &o, err, sizeof err), SWO_OK);
    assert_int_equal(swo_check(o, path("files/no/t.csv"), err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "No such file or directory"));
    /* no marker for files by path */
    assert_non_null(swo_open(o, path("files/t.csv"), err, sizeof err));
    assert_int_equal(swo_commit(o, err, sizeof err), SWO_OK);
    swo_free(o);
    assert_int_equal(entries(path("files")), 1);
}

/* as an unprivileged user (root's writes are not stopped by permissions) */
static void read_only_folder_refused(void **s)
{
    (void)s;
    assert_int_equal(mkdir(path("ro"), 0555), 0);
    chmod(path("ro"), 0555);
    const pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        if (geteuid() == 0 && (setgroups(0, NULL) != 0 || setgid(65534) != 0 || setuid(65534) != 0))
            _exit(77);
        if (geteuid() == 0)
            _exit(77);
        char err[600];
        swo_set *o = NULL;
        const swo_spec spec = { "test_swo", "--out", path("ro"), 1, 0 };
        if (swo_alloc(&spec, &o, err, sizeof err) != SWO_EREFUSED || !strstr(err, "is not writable"))
            _exit(1);
        const swo_spec fs = { "test_swo", "--out", NULL, 0, 0 };
        if (swo_alloc(&fs, &o, err, sizeof err) != SWO_OK)
            _exit(2);
        if (swo_check(o, path("ro/x.csv"), err, sizeof err) != SWO_EREFUSED || !strstr(err, "not writable"))
            _exit(3);
        if (swo_open(o, path("ro/x.csv"), err, sizeof err) || swo_code(o) != SWO_EREFUSED)
            _exit(4);
        swo_free(o);
        _exit(0);
    }
    int st;
    assert_int_equal(waitpid(pid, &st, 0), pid);
    assert_true(WIFEXITED(st));
    if (WEXITSTATUS(st) == 77)
        skip();
    assert_int_equal(WEXITSTATUS(st), 0);
    assert_int_equal(entries(path("ro")), 0);
}

/* a real full disk: a 64 KiB tmpfs (skipped where mounting is not permitted) */
static void full_disk_is_a_failure(void **s)
{
    (void)s;
    char err[600];
    assert_int_equal(mkdir(path("tiny"), 0755), 0);
    if (mount("tmpfs", path("tiny"), "tmpfs", 0, "size=64k") != 0)
        skip();
    assert_int_equal(mkdir(path("tiny/out"), 0755), 0);
    swo_set *o = NULL;
    const swo_spec spec = { "test_swo", "--out", path("tiny/out"), 0, 1 };
    int rc = swo_alloc(&spec, &o, err, sizeof err);
    FILE *f = rc == SWO_OK ? swo_open(o, "big.csv", err, sizeof err) : NULL;
    for (int k = 0; f && k < 20000; k++)
        fputs("0123456789012345678901234567890123456789\n", f);
    const int crc = f ? swo_commit(o, err, sizeof err) : -1;
    swo_free(o);
    const int left = entries(path("tiny/out"));
    umount(path("tiny"));
    assert_int_equal(rc, SWO_OK);
    assert_int_equal(crc, SWO_EFAIL);
    assert_non_null(strstr(err, "big.csv"));
    assert_non_null(strstr(err, "No space left on device"));
    assert_int_equal(left, 0);   /* no temporary, no marker, no file */
}

/* the opt-in clean-up: a tool killed while writing leaves nothing */
static void signal_cleans_up_when_on(void **s)
{
    (void)s;
    struct sigaction sa;
    assert_int_equal(sigaction(SIGTERM, NULL, &sa), 0);
    assert_true(sa.sa_handler == SIG_DFL || sa.sa_handler == SIG_IGN);   /* off by default */
    const pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        signal(SIGTERM, SIG_DFL);
        swo_signals_on();
        char err[600];
        swo_set *o = NULL;
        const swo_spec spec = { "test_swo", "--out", path("sig/deep"), 0, 1 };
        if (swo_alloc(&spec, &o, err, sizeof err) != SWO_OK)
            _exit(1);
        FILE *f = swo_open(o, "x.csv", err, sizeof err);
        if (!f || !swo_add(o, "y.png", err, sizeof err))
            _exit(2);
        put(path("sig/deep/scratch.gp"), "s\n");
        swo_signal_scratch(path("sig/deep/scratch.gp"));
        fputs("partial\n", f);
        fflush(f);
        raise(SIGTERM);
        _exit(3);
    }
    int st;
    assert_int_equal(waitpid(pid, &st, 0), pid);
    assert_true(WIFSIGNALED(st));
    assert_int_equal(WTERMSIG(st), SIGTERM);
    assert_int_equal(access(path("sig"), F_OK), -1);
}

static void lists_follow_the_rule(void **s)
{
    (void)s;
    char err[600], note[600];
    double *v = NULL;
    int n = 0;
    /* empty items: refused naming the option and the text */
    const char *bad[] = { "1,,3", ",1", "1,", ",", "" };
    for (size_t k = 0; k < sizeof bad / sizeof *bad; k++) {
        assert_int_equal(swo_list_numbers("--d", bad[k], 0, 10, 0, 0, &v, &n, note, sizeof note,
                                          err, sizeof err), SWO_EREFUSED);
        assert_null(v);
        assert_non_null(strstr(err, "--d: "));
        if (bad[k][0]) {
            char want[100];
            snprintf(want, sizeof want, "'%s' has an empty item", bad[k]);
            assert_non_null(strstr(err, want));
        }
    }
    /* a value twice (also written differently) */
    assert_int_equal(swo_list_numbers("--d", "1,2,1.0", 0, 10, 0, 0, &v, &n, note, sizeof note,
                                      err, sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "--d: '1,2,1.0' gives the value 1 twice (items 1 '1' and 3 '1.0')"));
    /* in order: kept, no note */
    assert_int_equal(swo_list_numbers("--d", "1,2,3", 0, 10, 0, 0, &v, &n, note, sizeof note, err,
                                      sizeof err), SWO_OK);
    assert_int_equal(n, 3);
    assert_string_equal(note, "");
    free(v);
    /* out of order: ascending, with the note */
    assert_int_equal(swo_list_numbers("--tau-plus", "10,0.3,3", 0, 1e4, 1, 64, &v, &n, note,
                                      sizeof note, err, sizeof err), SWO_OK);
    assert_int_equal(n, 3);
    assert_true(v[0] == 0.3 && v[1] == 3.0 && v[2] == 10.0);
    assert_string_equal(note, "--tau-plus: '10,0.3,3' taken in ascending order");
    free(v);
    /* range (open lower end), hexadecimal, not a number, too many */
    assert_int_equal(swo_list_numbers("--x", "0,1", 0, 1, 1, 0, &v, &n, note, sizeof note, err,
                                      sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "'0' (in '0,1') is out of range (0, 1]"));
    assert_int_equal(swo_list_numbers("--x", "0x1", 0, 10, 0, 0, &v, &n, note, sizeof note, err,
                                      sizeof err), SWO_EREFUSED);
    assert_int_equal(swo_list_numbers("--x", "1,nan", 0, 10, 0, 0, &v, &n, note, sizeof note, err,
                                      sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "not a finite number"));
    assert_int_equal(swo_list_numbers("--x", "1,2,3", 0, 10, 0, 2, &v, &n, note, sizeof note, err,
                                      sizeof err), SWO_EREFUSED);
    assert_non_null(strstr(err, "at most 2"));
    /* words: in the order given, each once, known ones only */
    const char *const words[] = { "hertz", "jkr-elastic", "jkr", NULL };
    int idx[16];
    assert_int_equal(swo_list_words("--cases", "jkr,hertz", words, 16, idx, &n, err, sizeof err),
                     SWO_OK);
    assert_int_equal(n, 2);
    assert_int_equal(idx[0], 2);
    assert_int_equal(idx[1], 0);
    assert_int_equal(swo_list_words("--cases", "jkr,jkr", words, 16, idx, &n, err, sizeof err),
                     SWO_EREFUSED);
    assert_non_null(strstr(err, "names 'jkr' twice"));
    assert_int_equal(swo_list_words("--cases", "hertz,,jkr", words, 16, idx, &n, err, sizeof err),
                     SWO_EREFUSED);
    assert_non_null(strstr(err, "empty item"));
    assert_int_equal(swo_list_words("--cases", "dmt", words, 16, idx, &n, err, sizeof err),
                     SWO_EREFUSED);
    assert_non_null(strstr(err, "'dmt' (in 'dmt') is not one of hertz, jkr-elastic, jkr"));
}

/* the one error formatter: the code returned, the message truncated to the
 * buffer, a NULL buffer left alone, bytes that are not printable ASCII as '?' */
static void errors_are_formatted_and_sanitized(void **state)
{
    (void)state;
    char err[16];
    assert_int_equal(swo_fail(7, err, sizeof err, "x %d is %s", 3, "bad"), 7);
    assert_string_equal(err, "x 3 is bad");
    assert_int_equal(swo_fail(-1, err, sizeof err, "%s", "a long message over the buffer"), -1);
    assert_string_equal(err, "a long message ");
    assert_int_equal(swo_fail(2, NULL, 0, "%s", "nothing written"), 2);
    err[0] = 'z';
    assert_int_equal(swo_fail(2, err, 0, "%s", "nothing written"), 2);
    assert_int_equal(err[0], 'z');
    assert_int_equal(swo_fail(1, err, sizeof err, "k\tv\x01\xff."), 1);
    assert_string_equal(err, "k?v??.");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(new_folder_gets_marker_and_abort_removes_it),
        cmocka_unit_test(empty_and_own_folders_are_written),
        cmocka_unit_test(foreign_folder_refused_unless_force),
        cmocka_unit_test(linked_or_non_folder_out_refused),
        cmocka_unit_test(non_regular_final_names_refused_and_left),
        cmocka_unit_test(device_node_refused_and_left),
        cmocka_unit_test(files_by_path_whole_or_nothing),
        cmocka_unit_test(read_only_folder_refused),
        cmocka_unit_test(full_disk_is_a_failure),
        cmocka_unit_test(signal_cleans_up_when_on),
        cmocka_unit_test(lists_follow_the_rule),
        cmocka_unit_test(errors_are_formatted_and_sanitized),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
