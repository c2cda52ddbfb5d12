/* swi_error.h - the photo comparison's error reporting (internal): a failing
 * function returns swi_fail(err, errlen, code, fmt, ...), the message
 * formatted into err by the libraries' one formatter (common/swo_err.h). */
#ifndef SWI_ERROR_H
#define SWI_ERROR_H

#include "swo_err.h"

#define swi_fail(err, errlen, code, ...) swo_fail(code, err, errlen, __VA_ARGS__)

#endif
