/* lh_alloc.h — allocation through a handle's allocator hooks (lh_allocator). */
#ifndef LH_ALLOC_H
#define LH_ALLOC_H

#include "lifthull.h"

/* The hooks to use: a copy of *user, or malloc/free when user is NULL.
 * Returns 0 when user is non-NULL but lacks alloc or free. */
int lh__allocator_init(lh_allocator *out, const lh_allocator *user);
void *lh__alloc(const lh_allocator *a, size_t size);
void lh__free(const lh_allocator *a, void *ptr);

#endif
