/* swx_lex.h - the lexer of the C core's dictionary files: regime.coeffs
 * (sww_load.c, doc/regime-coeffs.md) and deposition.coeffs (swd_load.c, the
 * near-wall closure). Private to wallmodel/core: not for hosts.
 *
 * Syntax: the subset of OpenFOAM dictionary syntax the two files share, cut
 * into tokens; what the tokens mean (keys, values, sub-dictionaries, the
 * messages about them) is the loaders' business.
 *   - blanks (isspace: space, tab, newline, CR, VT, FF) separate tokens; a
 *     newline counts a line (the first line is 1);
 *   - `// ...` to the end of the line and C comments are comments where a
 *     token would start;
 *   - ( ) { } ; are tokens of one byte each;
 *   - a word is the bytes up to a blank, one of ( ) { } ; or a NUL byte. At a
 *     NUL byte the lexer returns an empty word (len 0) and does not move on:
 *     each loader refuses an empty word;
 *   - with SWX_STRINGS, `"text"` is a string (no escapes, on one line), and a
 *     `"` also ends a word. Without it `"` is a byte of a word like any other.
 * The two files' dialects differ in details that both loaders keep:
 *   regime.coeffs      SWX_STRINGS | SWX_STRICT
 *   deposition.coeffs  0 (swx_next never fails)
 * SWX_STRICT: `//` and a C comment's start also end a word; a byte outside
 * isprint inside a word, a word longer than SWX_MAX_TOK - 1 bytes and a C
 * comment without its end are errors. Without it a word holds any byte but
 * the ones that end it, has any length (len; text cut to SWX_MAX_TOK - 1
 * bytes), and a C comment without its end runs to the end of the file.
 *
 * Limits: a token's text SWX_MAX_TOK - 1 bytes; a file swx_read's max bytes
 * (the caller's cap; the file is read whole into memory).
 *
 * Errors: a function returns SWX_OK (0) or a negative SWX_E*; the message is
 * in lx->err, naming the file and line ("FILE:LINE: what") or the file alone
 * for the file as a whole ("FILE: cannot open: ..."). Nothing is printed,
 * nothing exits. Numbers are not the lexer's: swx_number is the check both
 * loaders apply to a word. */
#ifndef SWX_LEX_H
#define SWX_LEX_H

#include <stddef.h>

#define SWX_MAX_TOK 256
#define SWX_ERRLEN 1024

enum { SWX_OK = 0, SWX_EPARSE = -1, SWX_EIO = -2, SWX_ENOMEM = -3, SWX_EBIG = -4 };

/* dialect flags of swx_read */
enum { SWX_STRINGS = 1, SWX_STRICT = 2 };

typedef enum {
    SWX_EOF, SWX_WORD, SWX_STRING, SWX_LPAR, SWX_RPAR, SWX_LBRACE, SWX_RBRACE, SWX_SEMI
} swx_kind;

typedef struct {
    const char *path;           /* the file's name, for the messages            */
    char *buf;                  /* its bytes (swx_read), freed by swx_done       */
    const char *p, *end;        /* the next byte to read, the end of the bytes   */
    int line;                   /* the line of p                                 */
    unsigned flags;             /* SWX_STRINGS, SWX_STRICT                       */
    /* the current token (swx_next) */
    swx_kind kind;
    int tline;                  /* the line it starts on                         */
    size_t len;                 /* its length as read (1 for ( ) { } ;, 0 at the
                                   end; a word's may be longer than text
                                   without SWX_STRICT)                           */
    char text[SWX_MAX_TOK];     /* a word's or string's bytes, the character of
                                   ( ) { } ;, "" at the end of the file          */
    char err[SWX_ERRLEN];       /* the message of the last error                 */
} swx_lex;

/* Read the regular file path (not a FIFO, which would wait for a writer) whole,
 * at most max bytes, and set lx to lex it from line 1 with flags; no token yet
 * (call swx_next). Returns SWX_OK, SWX_EIO ("FILE: cannot open: reason",
 * "FILE: not a regular file", "FILE: read error"), SWX_ENOMEM ("FILE: out of
 * memory") or SWX_EBIG ("FILE: file larger than MAX bytes"), lx holding no
 * buffer then. path must outlive lx. */
int swx_read(swx_lex *lx, const char *path, long max, unsigned flags);

/* Free what swx_read holds; lx may then be read again. */
void swx_done(swx_lex *lx);

/* Advance to the next token (kind, tline, len, text). Returns SWX_OK or, with
 * SWX_STRICT / SWX_STRINGS only, SWX_EPARSE with "FILE:LINE: what": a C
 * comment without its end (the line it starts on), "unexpected byte 0xHH",
 * "word longer than 255 characters", "string longer than 255 characters",
 * "unterminated string (missing \")". */
int swx_next(swx_lex *lx);

/* The current token for a message: "end of file", "'('", "')'", "'{'", "'}'",
 * "';'", or a word's or string's text. */
const char *swx_desc(const swx_lex *lx);

/* A strict number: the whole word converts (strtod), decimal only (no "0x":
 * strtod takes hexadecimal, OpenFOAM's reader does not). "nan", "inf" and a
 * value beyond the doubles (then +-HUGE_VAL) are numbers here: the loaders
 * decide. Returns 1 with *v set, else 0. */
int swx_number(const char *w, double *v);

#endif
