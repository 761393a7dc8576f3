/* Fuzz harness: JSON preset parsing, a --set edit and binding onto a nested schema. */
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "shitsukan/preset.h"

typedef struct f_elem {
    float v[2];
} f_elem;
typedef struct f_desc {
    float a;
    int n;
    int count;
    f_elem items[4];
    int mode;
    char name[8];
} f_desc;

static const sk_schema_field k_elem_fields[] = {
    {.key = NULL,
     .type = SK_FIELD_FLOATS,
     .offset = offsetof(f_elem, v),
     .min = -1,
     .max = 1,
     .count = 2,
     .count_offset = SK_FIELD_FIXED},
};
static const sk_schema k_elem = {"elem", k_elem_fields, 1, NULL};
static const char *const k_modes[] = {"default", "x", "y", NULL};
static const sk_schema_field k_fields[] = {
    {.key = "a", .type = SK_FIELD_FLOAT, .offset = offsetof(f_desc, a), .min = 0, .max = 1},
    {.key = "n", .type = SK_FIELD_INT, .offset = offsetof(f_desc, n), .min = 0, .max = 9},
    {.key = "items",
     .type = SK_FIELD_ARRAY,
     .offset = offsetof(f_desc, items),
     .count = 4,
     .min_count = 0,
     .count_offset = offsetof(f_desc, count),
     .elem_size = sizeof(f_elem),
     .schema = &k_elem},
    {.key = "mode", .type = SK_FIELD_ENUM, .offset = offsetof(f_desc, mode), .names = k_modes},
    {.key = "name", .type = SK_FIELD_STRING, .offset = offsetof(f_desc, name), .count = 8},
};
static const sk_schema k_schema = {"fuzz", k_fields, 5, NULL};

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_preset *p = NULL;
    if (sk_preset_parse(&p, (const char *)data, size, "fuzz", NULL) != SK_OK) return 0;
    sk_preset_set(p, "items[0][1]=0.5", NULL);
    f_desc d;
    memset(&d, 0, sizeof d);
    sk_preset_bind(p, &k_schema, &d, NULL);
    sk_preset_free(p);
    return 0;
}
