/* swi_error.c - the photo comparison's error reporting (see swi_error.h). */
#include "swi_error.h"

#include <stdarg.h>
#include <stdio.h>

int swi_fail(char *err, size_t errlen, int code, const char *fmt, ...)
{
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return code;
}
