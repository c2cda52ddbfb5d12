/* swd_internal.h - shared between swd.c and swd_load.c; not for hosts. */
#ifndef SWD_INTERNAL_H
#define SWD_INTERNAL_H

#include "swd.h"

/* Set the model's message to msg (a whole message, file and line included) and
 * return SWD_EINVAL. */
int swd_fail_message(swd_model *m, const char *msg);

#endif
