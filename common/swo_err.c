/* swo_err.c - the one formatter of the message a library function returns
 * (see swo_err.h). */
#include "swo_err.h"

#include <stdarg.h>
#include <stdio.h>

int swo_fail(int code, char *err, size_t errlen, const char *fmt, ...)
{
    if (!err || !errlen)
        return code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    for (char *c = err; *c; c++)
        if ((unsigned char)*c < 0x20 || (unsigned char)*c >= 0x7f)
            *c = '?';
    return code;
}
