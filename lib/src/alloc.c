/* alloc.c — the default allocator and the per-handle hooks. */
#include "lh_alloc.h"

#include <stdlib.h>

static void *default_alloc(void *user, size_t size)
{
    (void)user;
    return malloc(size ? size : 1);
}

static void default_free(void *user, void *ptr)
{
    (void)user;
    free(ptr);
}

int lh__allocator_init(lh_allocator *out, const lh_allocator *user)
{
    if (!user) {
        out->alloc = default_alloc;
        out->free = default_free;
        out->user = NULL;
        return 1;
    }
    if (!user->alloc || !user->free) return 0;
    *out = *user;
    return 1;
}

void *lh__alloc(const lh_allocator *a, size_t size) { return a->alloc(a->user, size); }

void lh__free(const lh_allocator *a, void *ptr)
{
    if (ptr) a->free(a->user, ptr);
}
