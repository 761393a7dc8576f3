/* A value sorted by a key, ties broken by its index: the order qsort gives the same on
 * every run and platform (qsort is not stable, so equal keys alone would not be). */
#ifndef SK_KEYED_INDEX_H
#define SK_KEYED_INDEX_H

#include <stdint.h>

typedef struct sk__keyed_index {
    double key;
    uint32_t index;
} sk__keyed_index;

/* qsort comparator of sk__keyed_index: increasing key, then increasing index. */
int sk__keyed_index_compare(const void *a, const void *b);

#endif
