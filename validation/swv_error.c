/* swv_error.c - the validation module's error reporting (see swv_error.h). */
#include "swv_error.h"

#include <stdarg.h>
#include <stdio.h>

int swv_fail(char *err, size_t errlen, int code, const char *fmt, ...)
{
    if (err && errlen) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err, errlen, fmt, ap);
        va_end(ap);
    }
    return code;
}
