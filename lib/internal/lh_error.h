/* lh_error.h — filling a caller's lh_error (lifthull.h, "error detail"); every
 * function accepts err == NULL and then does nothing. */
#ifndef LH_ERROR_H
#define LH_ERROR_H

#include "lifthull.h"

/* The success state: LH_OK, message "", line = column = 0, LH_ERROR_NO_INDEX. */
void lh__error_clear(lh_error *err);
/* A public function's last step: err->status = st, and err cleared when st is LH_OK
 * (no detail a failed stage wrote survives a success). Returns st. */
lh_status lh__error_done(lh_error *err, lh_status st);
/* Writes the printf-style message (cut to fit) and returns st; line, column and index
 * are left as they are. */
lh_status lh__error_say(lh_error *err, lh_status st, const char *fmt, ...)
#if defined(__GNUC__) || defined(__clang__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

#endif
