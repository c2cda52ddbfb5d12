/* swo_err.h - the one formatter of the message a library function returns.
 *
 * Every SnowWall library reports an error as a return code and a one-line
 * message in a caller's buffer (char *err, size_t errlen), never by printing
 * or exiting. swo_fail() writes that message and returns the code, so that a
 * check reads
 *
 *     if (!(x > 0))
 *         return swo_fail(-1, err, errlen, "x must be > 0, got %g", x);
 *
 * The message is truncated to the buffer; a NULL buffer or errlen 0 writes
 * nothing. Bytes that are not printable ASCII (binary data read as a config
 * file, a name with a control character) are written as '?', so that a
 * message never carries them to a terminal or a log. */
#ifndef SWO_ERR_H
#define SWO_ERR_H

#include <stddef.h>

int swo_fail(int code, char *err, size_t errlen, const char *fmt, ...)
    __attribute__((format(printf, 4, 5)));

#endif
