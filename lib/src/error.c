/* error.c — filling a caller's lh_error (lh_error.h). */
#include "lh_error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void lh__error_clear(lh_error *err)
{
    if (!err) return;
    err->status = LH_OK;
    err->line = 0;
    err->column = 0;
    err->index = LH_ERROR_NO_INDEX;
    memset(err->message, 0, sizeof err->message);
}

lh_status lh__error_done(lh_error *err, lh_status st)
{
    if (!err) return st;
    if (st == LH_OK) lh__error_clear(err);
    err->status = st;
    return st;
}

lh_status lh__error_say(lh_error *err, lh_status st, const char *fmt, ...)
{
    if (!err) return st;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
    return st;
}
