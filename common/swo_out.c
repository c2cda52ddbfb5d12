/* swo_out.c - atomic output sets with the output-folder contract, and the
 * clean-up of an interrupted tool (swo_out.h). */
#include "swo_out.h"

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

typedef struct {
    char *name;    /* as registered */
    char *final;   /* final path */
    char *tmp;     /* temporary path in the same folder */
    FILE *fp;      /* open stream or NULL */
    int external;  /* swo_add: written by a writer of its own, non-empty at commit */
    volatile sig_atomic_t live;   /* the temporary exists */
} swo_file;

struct swo_set {
    char *opt;
    char *tool;
    char *dir;                /* NULL: names are paths */
    char **created;           /* folders this set created, innermost first */
    int ncreated;
    int mark;                 /* the folder is the set's: write the marker */
    char *note;               /* written into a foreign folder by force */
    swo_file *f;
    int n, cap;
    volatile sig_atomic_t done;   /* committed or aborted */
    int code;
};

/* ---- signals ------------------------------------------------------------ */

#define SWO_MAXSETS 16
static swo_set *volatile g_sets[SWO_MAXSETS];
static volatile sig_atomic_t g_installed;
static volatile pid_t g_child;
static char g_scratch[4200];
static volatile sig_atomic_t g_scratch_on;
static const int g_sigs[] = { SIGINT, SIGTERM, SIGHUP };

static void clean_set(swo_set *o)
{
    for (int i = 0; i < o->n; i++)
        if (o->f[i].live)
            unlink(o->f[i].tmp);
    for (int k = 0; k < o->ncreated; k++)
        rmdir(o->created[k]);
}

static void on_signal(int sig)
{
    /* the child first: stopped and reaped before the temporaries go, else it
     * writes its file after they were removed */
    const pid_t child = g_child;
    if (child > 0) {
        kill(child, SIGTERM);
        while (waitpid(child, NULL, 0) < 0 && errno == EINTR)
            ;
    }
    if (g_scratch_on)
        unlink(g_scratch);
    for (int k = 0; k < SWO_MAXSETS; k++) {
        swo_set *o = g_sets[k];
        if (o && !o->done)
            clean_set(o);
    }
    signal(sig, SIG_DFL);
    raise(sig);
}

void swo_signals_on(void)
{
    if (g_installed)
        return;
    g_installed = 1;
    for (size_t k = 0; k < sizeof g_sigs / sizeof *g_sigs; k++) {
        struct sigaction sa;
        /* a signal the tool was started with ignored (nohup, a background
         * job) stays ignored */
        if (sigaction(g_sigs[k], NULL, &sa) == 0 && sa.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        for (size_t j = 0; j < sizeof g_sigs / sizeof *g_sigs; j++)
            sigaddset(&sa.sa_mask, g_sigs[j]);
        sigaction(g_sigs[k], &sa, NULL);
    }
}

void swo_signal_child(pid_t pid)
{
    g_child = pid;
}

void swo_signal_scratch(const char *path)
{
    g_scratch_on = 0;
    if (path) {
        snprintf(g_scratch, sizeof g_scratch, "%s", path);
        g_scratch_on = 1;
    }
}

/* The set's bookkeeping changes with the signals held when the handler is on,
 * so that it never sees half an entry. */
static void hold(sigset_t *old)
{
    if (!g_installed)
        return;
    sigset_t s;
    sigemptyset(&s);
    for (size_t j = 0; j < sizeof g_sigs / sizeof *g_sigs; j++)
        sigaddset(&s, g_sigs[j]);
    pthread_sigmask(SIG_BLOCK, &s, old);
}

static void release(const sigset_t *old)
{
    if (g_installed)
        pthread_sigmask(SIG_SETMASK, old, NULL);
}

static void watch(swo_set *o, int on)
{
    for (int k = 0; k < SWO_MAXSETS; k++) {
        if (on && !g_sets[k]) {
            g_sets[k] = o;
            return;
        }
        if (!on && g_sets[k] == o) {
            g_sets[k] = NULL;
            return;
        }
    }
}

/* ---- helpers ------------------------------------------------------------ */

static char *sdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

static int fail(swo_set *o, int code, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 5, 6)));
static int fail(swo_set *o, int code, char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    if (o)
        o->code = code;
    return code;
}

static const char *kind_of(mode_t m)
{
    return S_ISDIR(m) ? "a folder" : S_ISLNK(m) ? "a symbolic link" : S_ISCHR(m) ? "a character device"
         : S_ISBLK(m) ? "a block device" : S_ISFIFO(m) ? "a FIFO" : S_ISSOCK(m) ? "a socket"
         : "not a regular file";
}

/* errno of a file that cannot be made: the place (a missing, unwritable or
 * read-only folder) is the user's input; anything else a system failure */
static int code_of(int e)
{
    return (e == EACCES || e == EPERM || e == ENOENT || e == ENOTDIR || e == EROFS || e == ENAMETOOLONG)
         ? SWO_EREFUSED : SWO_EFAIL;
}

static int add_created(swo_set *o, const char *p)
{
    char **c = realloc(o->created, (size_t)(o->ncreated + 1) * sizeof *c);
    if (!c)
        return -1;
    o->created = c;
    char *s = sdup(p);
    if (!s)
        return -1;
    /* innermost first */
    memmove(c + 1, c, (size_t)o->ncreated * sizeof *c);
    c[0] = s;
    o->ncreated++;
    return 0;
}

/* The output folder: created when missing (with its parents when asked). */
static int make_folder(swo_set *o, const char *dir, int parents, char *err, size_t errlen)
{
    char *p = sdup(dir);
    if (!p)
        return fail(o, SWO_EFAIL, err, errlen, "out of memory");
    size_t len = strlen(p);
    if (!parents) {
        if (mkdir(p, 0777) != 0) {
            const int e = errno;
            free(p);
            if (e == ENOENT)
                return fail(o, SWO_EREFUSED, err, errlen, "%s: cannot create '%s': its parent "
                            "folder does not exist", o->opt, dir);
            return fail(o, code_of(e), err, errlen, "%s: cannot create '%s': %s", o->opt, dir,
                        strerror(e));
        }
        int rc = add_created(o, p);
        free(p);
        return rc ? fail(o, SWO_EFAIL, err, errlen, "out of memory") : SWO_OK;
    }
    for (size_t k = 1; k <= len; k++) {
        if (p[k] != '/' && p[k] != '\0')
            continue;
        const char c = p[k];
        p[k] = '\0';
        struct stat st;
        if (stat(p, &st) != 0) {
            if (mkdir(p, 0777) != 0) {
                const int e = errno;
                fail(o, code_of(e), err, errlen, "%s: cannot create folder '%s': %s", o->opt, p,
                     strerror(e));
                free(p);
                return o->code;
            }
            if (add_created(o, p) != 0) {
                free(p);
                return fail(o, SWO_EFAIL, err, errlen, "out of memory");
            }
        } else if (!S_ISDIR(st.st_mode)) {
            fail(o, SWO_EREFUSED, err, errlen, "%s: '%s' exists and is not a folder", o->opt, p);
            free(p);
            return o->code;
        }
        p[k] = c;
    }
    free(p);
    return SWO_OK;
}

/* An existing folder: empty or the set's (the marker), or foreign. */
static int check_folder(swo_set *o, const char *dir, int force, char *err, size_t errlen)
{
    if (access(dir, W_OK | X_OK) != 0)
        return fail(o, SWO_EREFUSED, err, errlen, "%s: '%s' is not writable (%s)", o->opt, dir,
                    strerror(errno));
    DIR *d = opendir(dir);
    if (!d)
        return fail(o, SWO_EREFUSED, err, errlen, "%s: cannot read folder '%s': %s", o->opt, dir,
                    strerror(errno));
    int marker = 0;
    char *foreign = NULL;   /* the smallest foreign name, for a message that does not vary */
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        const char *nm = e->d_name;
        if (!strcmp(nm, ".") || !strcmp(nm, ".."))
            continue;
        if (!strcmp(nm, SWO_MARKER)) {
            struct stat st;
            char path[4400];
            snprintf(path, sizeof path, "%s/%s", dir, nm);
            if (lstat(path, &st) == 0 && S_ISREG(st.st_mode)) {
                marker = 1;
                continue;
            }
        }
        if (!foreign || strcmp(nm, foreign) < 0) {
            free(foreign);
            foreign = sdup(nm);
        }
    }
    closedir(d);
    if (marker || !foreign) {
        free(foreign);
        o->mark = 1;
        return SWO_OK;
    }
    if (!force) {
        fail(o, SWO_EREFUSED, err, errlen, "%s: '%s' is not empty and not a SnowWall output folder "
             "(holds '%s'); give --force to write into it", o->opt, dir, foreign);
        free(foreign);
        return o->code;
    }
    char buf[4600];
    snprintf(buf, sizeof buf, "--force: writing into '%s', which is not a SnowWall output folder "
             "(holds '%s'): files of the same names are replaced, no other file is touched",
             dir, foreign);
    free(foreign);
    o->note = sdup(buf);
    return SWO_OK;
}

int swo_alloc(const swo_spec *spec, swo_set **out, char *err, size_t errlen)
{
    *out = NULL;
    swo_set *o = calloc(1, sizeof *o);
    if (!o)
        return fail(NULL, SWO_EFAIL, err, errlen, "out of memory");
    o->opt = sdup(spec->opt ? spec->opt : "--out");
    o->tool = sdup(spec->tool ? spec->tool : "SnowWall");
    int rc = (o->opt && o->tool) ? SWO_OK : fail(o, SWO_EFAIL, err, errlen, "out of memory");
    if (rc == SWO_OK && spec->dir) {
        if (!*spec->dir) {
            rc = fail(o, SWO_EREFUSED, err, errlen, "%s: empty folder name", o->opt);
        } else if (!(o->dir = sdup(spec->dir))) {
            rc = fail(o, SWO_EFAIL, err, errlen, "out of memory");
        } else {
            /* "DIR/" names the link's target: the link itself is looked at */
            size_t len = strlen(o->dir);
            while (len > 1 && o->dir[len - 1] == '/')
                o->dir[--len] = '\0';
            struct stat st;
            if (lstat(o->dir, &st) == 0) {
                if (S_ISLNK(st.st_mode))
                    rc = fail(o, SWO_EREFUSED, err, errlen, "%s: '%s' is a symbolic link; give "
                              "the folder itself", o->opt, spec->dir);
                else if (!S_ISDIR(st.st_mode))
                    rc = fail(o, SWO_EREFUSED, err, errlen, "%s: '%s' exists and is not a folder "
                              "(%s)", o->opt, spec->dir, kind_of(st.st_mode));
                else
                    rc = check_folder(o, o->dir, spec->force, err, errlen);
            } else if (errno == ENOENT) {
                rc = make_folder(o, o->dir, spec->parents, err, errlen);
                o->mark = 1;
            } else {
                rc = fail(o, code_of(errno), err, errlen, "%s: '%s': %s", o->opt, spec->dir,
                          strerror(errno));
            }
        }
    }
    if (rc != SWO_OK) {
        for (int k = 0; k < o->ncreated; k++)
            rmdir(o->created[k]);
        o->done = 1;
        swo_free(o);
        return rc;
    }
    sigset_t old;
    hold(&old);
    watch(o, 1);
    release(&old);
    *out = o;
    return SWO_OK;
}

const char *swo_note(const swo_set *o)
{
    return o ? o->note : NULL;
}

int swo_code(const swo_set *o)
{
    return o && o->code ? o->code : SWO_EFAIL;
}

static char *final_path(const swo_set *o, const char *name)
{
    size_t len = strlen(name) + (o->dir ? strlen(o->dir) : 0) + 2;
    char *p = malloc(len);
    if (!p)
        return NULL;
    if (o->dir)
        snprintf(p, len, "%s/%s", o->dir, name);
    else
        snprintf(p, len, "%s", name);
    return p;
}

/* the final name: absent or a regular file (a link is not followed) */
static int check_final(swo_set *o, const char *final, char *err, size_t errlen)
{
    struct stat st;
    if (lstat(final, &st) == 0) {
        if (!S_ISREG(st.st_mode))
            return fail(o, SWO_EREFUSED, err, errlen, "cannot write '%s': it exists and is %s; "
                        "it is left as it is", final, kind_of(st.st_mode));
    } else if (errno != ENOENT) {
        return fail(o, code_of(errno), err, errlen, "cannot write '%s': %s", final, strerror(errno));
    }
    return SWO_OK;
}

int swo_check(swo_set *o, const char *name, char *err, size_t errlen)
{
    if (!name || !*name)
        return fail(o, SWO_EREFUSED, err, errlen, "%s: empty file name", o->opt);
    char *final = final_path(o, name);
    if (!final)
        return fail(o, SWO_EFAIL, err, errlen, "out of memory");
    int rc = check_final(o, final, err, errlen);
    if (rc == SWO_OK && !o->dir) {
        /* a path of its own: its folder must be there and take files */
        const char *slash = strrchr(final, '/');
        char *dir = slash ? sdup(final) : sdup(".");
        if (!dir) {
            rc = fail(o, SWO_EFAIL, err, errlen, "out of memory");
        } else {
            if (slash)
                dir[slash == final ? 1 : slash - final] = '\0';
            struct stat st;
            if (stat(dir, &st) != 0)
                rc = fail(o, SWO_EREFUSED, err, errlen, "cannot write '%s': folder '%s': %s", final,
                          dir, strerror(errno));
            else if (!S_ISDIR(st.st_mode))
                rc = fail(o, SWO_EREFUSED, err, errlen, "cannot write '%s': '%s' is not a folder",
                          final, dir);
            else if (access(dir, W_OK | X_OK) != 0)
                rc = fail(o, SWO_EREFUSED, err, errlen, "cannot write '%s': folder '%s' is not "
                          "writable (%s)", final, dir, strerror(errno));
            free(dir);
        }
    }
    free(final);
    return rc;
}

/* A new file of a name ending in XXXXXX (replaced by random characters),
 * created exclusively (never through a link or over anything that is there)
 * with mode 0666 less the umask, as any output file; unlike mkstemp's 0600 it
 * needs no umask() call, which would race with the host's other threads. */
static int make_temp(char *tmpl)
{
    static const char cs[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    static unsigned long long state;
    const size_t len = strlen(tmpl);
    struct timespec ts;
    clock_gettime(CLOCK_REALTIME, &ts);
    state ^= (unsigned long long)ts.tv_nsec ^ ((unsigned long long)ts.tv_sec << 30)
           ^ ((unsigned long long)getpid() << 12);
    for (int attempt = 0; attempt < 1000; attempt++) {
        for (size_t k = len - 6; k < len; k++) {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            tmpl[k] = cs[(state >> 33) % (sizeof cs - 1)];
        }
        const int fd = open(tmpl, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
        if (fd >= 0 || errno != EEXIST)
            return fd;
    }
    errno = EEXIST;
    return -1;
}

static swo_file *find(const swo_set *o, const char *name)
{
    for (int i = 0; i < o->n; i++)
        if (strcmp(o->f[i].name, name) == 0)
            return &o->f[i];
    return NULL;
}

/* register name; *fd gets the temporary's open descriptor (or -1 when it was
 * registered before) */
static swo_file *add_file(swo_set *o, const char *name, int *fd, char *err, size_t errlen)
{
    *fd = -1;
    if (o->done) {
        fail(o, SWO_EFAIL, err, errlen, "output set already finished");
        return NULL;
    }
    swo_file *e = find(o, name);
    if (e)
        return e;
    if (swo_check(o, name, err, errlen) != SWO_OK)
        return NULL;
    char *final = final_path(o, name);
    const size_t len = (final ? strlen(final) : 0) + 16;
    char *tmp = final ? malloc(len) : NULL;
    char *nm = sdup(name);
    if (!final || !tmp || !nm) {
        free(final); free(tmp); free(nm);
        fail(o, SWO_EFAIL, err, errlen, "out of memory");
        return NULL;
    }
    const char *slash = strrchr(final, '/');
    if (slash)
        snprintf(tmp, len, "%.*s.tmp-%s.XXXXXX", (int)(slash - final + 1), final, slash + 1);
    else
        snprintf(tmp, len, ".tmp-%s.XXXXXX", final);
    sigset_t old;
    hold(&old);
    if (o->n == o->cap) {
        const int cap = o->cap ? 2 * o->cap : 16;
        swo_file *f = malloc((size_t)cap * sizeof *f);
        if (!f) {
            release(&old);
            free(final); free(tmp); free(nm);
            fail(o, SWO_EFAIL, err, errlen, "out of memory");
            return NULL;
        }
        if (o->n)
            memcpy(f, o->f, (size_t)o->n * sizeof *f);
        swo_file *was = o->f;
        o->f = f;    /* a pointer swap: the handler sees the old or the new array whole */
        o->cap = cap;
        free(was);
    }
    const int d = make_temp(tmp);
    if (d < 0) {
        const int e2 = errno;
        release(&old);
        fail(o, code_of(e2), err, errlen, "cannot write '%s': %s", final, strerror(e2));
        free(final); free(tmp); free(nm);
        return NULL;
    }
    e = &o->f[o->n];
    e->name = nm;
    e->final = final;
    e->tmp = tmp;
    e->fp = NULL;
    e->external = 0;
    e->live = 1;
    o->n++;
    release(&old);
    *fd = d;
    return e;
}

const char *swo_add(swo_set *o, const char *name, char *err, size_t errlen)
{
    int fd;
    swo_file *e = add_file(o, name, &fd, err, errlen);
    if (!e)
        return NULL;
    if (fd >= 0) {
        close(fd);
        e->external = 1;
    }
    return e->tmp;
}

FILE *swo_open(swo_set *o, const char *name, char *err, size_t errlen)
{
    int fd;
    swo_file *e = add_file(o, name, &fd, err, errlen);
    if (!e)
        return NULL;
    if (e->fp)
        return e->fp;
    if (fd < 0) {
        /* registered by swo_add before: the temporary is the set's own file */
        fd = open(e->tmp, O_WRONLY | O_TRUNC | O_NOFOLLOW);
        if (fd < 0) {
            fail(o, SWO_EFAIL, err, errlen, "cannot write '%s': %s", e->final, strerror(errno));
            return NULL;
        }
    }
    e->external = 0;
    e->fp = fdopen(fd, "w");
    if (!e->fp) {
        fail(o, SWO_EFAIL, err, errlen, "cannot write '%s': %s", e->final, strerror(errno));
        close(fd);
        return NULL;
    }
    return e->fp;
}

const char *swo_final(const swo_set *o, const char *name)
{
    const swo_file *e = find(o, name);
    return e ? e->final : NULL;
}

/* close a stream with every error checked: buffered data, the disk's own
 * (fsync) and close's */
static int close_checked(FILE *f)
{
    int bad = fflush(f) != 0 || ferror(f);
    int e = bad ? errno : 0;
    if (!bad && fsync(fileno(f)) != 0 && errno != EINVAL && errno != EROFS) {
        bad = 1;
        e = errno;
    }
    if (fclose(f) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    if (bad)
        errno = e ? e : EIO;
    return bad ? -1 : 0;
}

int swo_commit(swo_set *o, char *err, size_t errlen)
{
    if (o->done)
        return fail(o, SWO_EFAIL, err, errlen, "output set already finished");
    if (o->mark) {
        FILE *m = swo_open(o, SWO_MARKER, err, errlen);
        if (!m) {
            const int c = o->code;
            swo_abort(o);
            return o->code = c;
        }
        char when[64] = "unknown";
        const time_t t = time(NULL);
        struct tm tm;
        if (gmtime_r(&t, &tm))
            strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &tm);
        fprintf(m, "SnowWall output folder\ntool: %s\nwritten: %s\n", o->tool, when);
    }
    for (int i = 0; i < o->n; i++) {
        swo_file *e = &o->f[i];
        if (e->fp) {
            FILE *f = e->fp;
            e->fp = NULL;
            if (close_checked(f) != 0) {
                fail(o, SWO_EFAIL, err, errlen, "write error on '%s': %s", e->final,
                     strerror(errno));
                swo_abort(o);
                return SWO_EFAIL;
            }
        } else if (e->external) {
            struct stat st;
            if (stat(e->tmp, &st) != 0 || st.st_size == 0) {
                fail(o, SWO_EFAIL, err, errlen, "output '%s' was not produced", e->final);
                swo_abort(o);
                return SWO_EFAIL;
            }
        }
    }
    /* every final name checked again before the first rename */
    for (int i = 0; i < o->n; i++)
        if (check_final(o, o->f[i].final, err, errlen) != SWO_OK) {
            const int c = o->code;
            swo_abort(o);
            return o->code = c;
        }
    sigset_t old;
    hold(&old);
    for (int i = 0; i < o->n; i++) {
        if (rename(o->f[i].tmp, o->f[i].final) != 0) {
            fail(o, SWO_EFAIL, err, errlen, "cannot rename to '%s': %s", o->f[i].final,
                 strerror(errno));
            release(&old);
            swo_abort(o);
            return SWO_EFAIL;
        }
        o->f[i].live = 0;
    }
    o->done = 1;
    release(&old);
    return SWO_OK;
}

void swo_abort(swo_set *o)
{
    if (!o || o->done)
        return;
    sigset_t old;
    hold(&old);
    for (int i = 0; i < o->n; i++) {
        if (o->f[i].fp) {
            fclose(o->f[i].fp);
            o->f[i].fp = NULL;
        }
        if (o->f[i].live) {
            unlink(o->f[i].tmp);
            o->f[i].live = 0;
        }
    }
    for (int k = 0; k < o->ncreated; k++)
        if (rmdir(o->created[k]) != 0)
            break;
    o->done = 1;
    release(&old);
}

void swo_free(swo_set *o)
{
    if (!o)
        return;
    swo_abort(o);
    sigset_t old;
    hold(&old);
    watch(o, 0);
    release(&old);
    for (int i = 0; i < o->n; i++) {
        free(o->f[i].name);
        free(o->f[i].final);
        free(o->f[i].tmp);
    }
    for (int k = 0; k < o->ncreated; k++)
        free(o->created[k]);
    free(o->created);
    free(o->f);
    free(o->dir);
    free(o->opt);
    free(o->tool);
    free(o->note);
    free(o);
}
