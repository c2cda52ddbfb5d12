/* swo_out.h - the one output writer of every SnowWall C tool, and its
 * strict comma-list parser.
 *
 * An output set is a group of files that appear whole or not at all:
 *
 *   - every file is written to a temporary in its own folder
 *     (".tmp-NAME.XXXXXX", created exclusively, so never through a planted
 *     link; mode 0666 less the umask),
 *     flushed, synced and closed with every error checked (a full disk is a
 *     failure), and renamed to its final name only by swo_commit();
 *   - a final name is replaced only when it is absent or a regular file: a
 *     folder, device, FIFO, socket or symbolic link there is refused and left
 *     untouched;
 *   - on any failure (and, once swo_signals_on() was called, on SIGINT,
 *     SIGTERM or SIGHUP) the temporaries are removed, and the folders the set
 *     created are removed again; nothing the set did not write is deleted.
 *
 * With an output folder (swo_spec.dir) the set implements the output-folder
 * contract: the folder is a SnowWall output folder when it holds a regular file
 * ".snowwall-output" (first line "SnowWall output folder", then "tool: NAME"
 * and "written: <ISO-8601 UTC time>"). A missing folder is created; a folder
 * that is empty or holds the marker is written into, and gets the marker (in
 * the same commit); a folder holding anything else and no marker is refused
 * unless spec.force, and then written into without a marker; a symbolic link
 * or a non-folder is refused. The checks are made by swo_alloc(), before the
 * tool's work.
 *
 * Without a folder (spec.dir NULL) every name is a path of its own (a
 * single-file option such as --out FILE or --trace-vtk FILE): its folder must
 * exist and be writable.
 *
 * Return codes are exit statuses: SWO_OK 0, SWO_EFAIL 1 (a system failure: a
 * write error, a full disk, a failed rename), SWO_EREFUSED 2 (refused input: a
 * foreign, linked, unwritable or non-folder --out, a non-regular final name).
 * Messages are one line without the tool's name: the caller prints
 * "TOOL: MESSAGE". Nothing here prints or exits. Not thread-safe: one thread
 * writes a set.
 */
#ifndef SWO_OUT_H
#define SWO_OUT_H

#include <stddef.h>
#include <stdio.h>
#include <sys/types.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { SWO_OK = 0, SWO_EFAIL = 1, SWO_EREFUSED = 2 };

#define SWO_MARKER ".snowwall-output"

typedef struct {
    const char *tool;   /* the marker's "tool: NAME" (e.g. "snowregime map") */
    const char *opt;    /* the option named in messages (NULL: "--out") */
    const char *dir;    /* the output folder, or NULL: names are paths */
    int force;          /* write into a non-empty folder that is not an output folder */
    int parents;        /* create missing parent folders too (else the parent must exist) */
} swo_spec;

typedef struct swo_set swo_set;

/* Check the output folder (or, without one, nothing yet), create it when
 * missing, and return the set in *out. SWO_OK, or a code and a message
 * ("--out: 'DIR' is not empty and not a SnowWall output folder (holds 'x');
 * give --force to write into it"). */
int swo_alloc(const swo_spec *spec, swo_set **out, char *err, size_t errlen);

/* A note for the user when the set writes into a foreign folder by force
 * ("--force: writing into 'DIR', which is not a SnowWall output folder; files
 * of other names are left alone"), else NULL. */
const char *swo_note(const swo_set *o);

/* Check that `name` can be written (absent or a regular file; without a
 * folder: its own folder exists and is writable) without creating anything:
 * for the tool's fixed names, before its work. SWO_OK or SWO_EREFUSED. */
int swo_check(swo_set *o, const char *name, char *err, size_t errlen);

/* Register `name` (a file name inside the folder, or a path without one),
 * create its temporary and return the temporary's path (valid until the set
 * is freed) for a writer of its own (a child process): the file must be
 * non-empty at commit. Registering a name twice returns the same path.
 * NULL on failure (swo_code() tells which). */
const char *swo_add(swo_set *o, const char *name, char *err, size_t errlen);
/* swo_add() and a stream on the temporary: closed (errors checked) by
 * swo_commit(), closed and removed by swo_abort(). */
FILE *swo_open(swo_set *o, const char *name, char *err, size_t errlen);
/* The final path of a registered name, or NULL. */
const char *swo_final(const swo_set *o, const char *name);
/* The code of the last failure of the set (SWO_EFAIL or SWO_EREFUSED). */
int swo_code(const swo_set *o);

/* Write the marker (when the folder is the set's), close every stream with
 * its errors checked, check every final name again, and rename every
 * temporary to its final name. On failure the set is aborted: SWO_EFAIL or
 * SWO_EREFUSED with a message. */
int swo_commit(swo_set *o, char *err, size_t errlen);
/* Remove every temporary and the folders the set created. */
void swo_abort(swo_set *o);
/* Free (aborts first when neither commit nor abort was called). NULL is fine. */
void swo_free(swo_set *o);

/* Opt-in clean-up on SIGINT, SIGTERM and SIGHUP for a command-line tool: the
 * handler stops and reaps the child given by swo_signal_child(), removes the
 * scratch file of swo_signal_scratch() and the temporaries and created folders
 * of every live set (async-signal-safe calls only), then dies of the signal.
 * A library running inside a host process (the Code_Saturne binding) never
 * calls it. */
void swo_signals_on(void);
/* The child process being waited for (0: none), stopped first by the handler. */
void swo_signal_child(pid_t pid);
/* A scratch file of the tool to remove on a signal (NULL: none; copied). */
void swo_signal_scratch(const char *path);

/* ---- comma lists -------------------------------------------------------
 * The rule of every list option: items separated by single commas, no empty
 * item ("1,,3", ",1", "1," are refused naming the option and the text), no
 * value twice; a numeric list given out of order is taken in ascending order
 * and the parser says so in `note` ("--OPT: 'TEXT' taken in ascending order";
 * empty when the order was kept), for the caller to print as
 * "TOOL: note: NOTE" on stderr. */

/* A numeric list: decimal numbers (no hexadecimal, finite), each in
 * [lo, hi] ((lo, hi] with lo_open), at most maxn of them (0: no limit), into
 * a new array (free() it) sorted ascending; *n gets the count (>= 1).
 * SWO_OK, or SWO_EREFUSED with "OPT: ..." in err. */
int swo_list_numbers(const char *opt, const char *text, double lo, double hi, int lo_open,
                     int maxn, double **out, int *n, char *note, size_t notelen,
                     char *err, size_t errlen);
/* A list of words, each one of the NULL-terminated `words`, in the order
 * given, at most maxn (0: no limit): idx[k] gets the word's index in `words`
 * (idx has room for maxn, or for every comma + 1 when maxn is 0).
 * SWO_OK, or SWO_EREFUSED with a message. */
int swo_list_words(const char *opt, const char *text, const char *const *words, int maxn,
                   int *idx, int *n, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif
#endif
