/* status.c — messages and names of the pinned status codes (one X-macro list in
 * lifthull.h makes both the enum and these tables). */
#include "lifthull.h"

const char *lh_status_message(lh_status status)
{
    switch (status) {
#define LH_STATUS_MSG_(name, value, msg) case name: return msg;
        LH_STATUS_LIST(LH_STATUS_MSG_)
#undef LH_STATUS_MSG_
    }
    return "unknown status";
}

const char *lh_status_name(lh_status status)
{
    switch (status) {
#define LH_STATUS_NAME_(name, value, msg) case name: return #name;
        LH_STATUS_LIST(LH_STATUS_NAME_)
#undef LH_STATUS_NAME_
    }
    return "unknown status";
}
