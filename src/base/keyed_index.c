/* The key/index comparator (src/base/keyed_index.h). */
#include "base/keyed_index.h"

int sk__keyed_index_compare(const void *a, const void *b)
{
    const sk__keyed_index *x = a, *y = b;
    if (x->key != y->key) return x->key < y->key ? -1 : 1;
    return x->index < y->index ? -1 : (x->index > y->index);
}
