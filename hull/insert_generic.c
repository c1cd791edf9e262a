/* insert_generic.c — the insertion loop (insert_impl.h) with the dimension a
 * runtime value and the caller's conflict test: every d, every mode. */
#define LH_T_NAME lh__eng_insert_generic
#include "insert_impl.h"
