/* io_plc_stubs.c — placeholders for the PLC readers not written yet (each moves to
 * its own io_plc_<format>.c). */
#include "io_plc.h"

static lh_status not_yet(lh__scan *s, const char *what)
{
    return lh__error_say(s->err, LH_ERR_PARSE, "%s: %s files are not read yet", s->name, what);
}

lh_status lh__plc_read_ply(lh__scan *s, lh__plc_build *b) { (void)b; return not_yet(s, "PLY"); }
lh_status lh__plc_read_stl(lh__scan *s, lh__plc_build *b) { (void)b; return not_yet(s, "STL"); }
