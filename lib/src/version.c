/* version.c — run-time version of the library. */
#include "lifthull.h"

int lh_version_number(void)
{
    return LH_VERSION_MAJOR * 10000 + LH_VERSION_MINOR * 100 + LH_VERSION_PATCH;
}

const char *lh_version_string(void) { return LH_VERSION_STRING; }

int lh_index_bits(void) { return LH_INDEX_BITS; }
