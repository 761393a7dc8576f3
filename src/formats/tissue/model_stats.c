/* The built model's counts and where its build time went, as JSON (the skin generation of
 * Shigemori & Kawai sec. 4: voxels, dilation, isosurface, classification, springs). */
#include <cjson/cJSON.h>
#include <stddef.h>

#include "formats/json_file.h"
#include "models/tissue/tissue_internal.h"

typedef struct stat_key {
    const char *key;
    size_t offset; /* of a size_t (counts) or a double (seconds) in sk_tissue_model_stats */
} stat_key;

#define STAT(k, field)                                                                             \
    {                                                                                              \
        k, offsetof(sk_tissue_model_stats, field)                                                  \
    }
static const stat_key point_keys[] = {STAT("skin", skin_points), STAT("fat", fat_points),
                                      STAT("muscle", muscle_points), STAT("bone", bone_points),
                                      STAT("total", points)};
static const stat_key spring_keys[] = {STAT("skin", skin_springs),
                                       STAT("skin_fat", skin_fat_springs), STAT("fat", fat_springs),
                                       STAT("fat_tissue", anchor_springs), STAT("total", springs)};
static const stat_key second_keys[] = {
    STAT("voxelise", seconds_voxelise), STAT("fat_regions", seconds_fat),
    STAT("dilate", seconds_dilate),     STAT("extract", seconds_extract),
    STAT("classify", seconds_classify), STAT("springs", seconds_springs),
    STAT("total", seconds_total)};
#define COUNT_OF(a) ((int)(sizeof(a) / sizeof((a)[0])))

static void add_group(cJSON *o, const char *name, const sk_tissue_model_stats *s,
                      const stat_key *keys, int n, bool counts)
{
    cJSON *group = cJSON_AddObjectToObject(o, name);
    const unsigned char *base = (const unsigned char *)s;
    for (int i = 0; i < n; i++) {
        const void *v = base + keys[i].offset;
        cJSON_AddNumberToObject(group, keys[i].key,
                                counts ? (double)*(const size_t *)v : *(const double *)v);
    }
}

cJSON *sk__model_stats_json(const sk_tissue_model *m)
{
    const sk_tissue_model_stats *s = &m->stats;
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON_AddStringToObject(o, "character", m->desc.name);
    cJSON *grid = cJSON_AddArrayToObject(o, "grid");
    for (int k = 0; k < 3; k++) cJSON_AddItemToArray(grid, cJSON_CreateNumber(s->grid[k]));
    cJSON_AddNumberToObject(o, "spacing_mm", s->spacing_mm);
    cJSON_AddNumberToObject(o, "tissue_voxels", (double)s->tissue_voxels);
    add_group(o, "points", s, point_keys, COUNT_OF(point_keys), true);
    add_group(o, "springs", s, spring_keys, COUNT_OF(spring_keys), true);
    cJSON_AddNumberToObject(o, "skin_triangles", (double)s->skin_triangles);
    cJSON_AddNumberToObject(o, "removed_cells", (double)s->removed_cells);
    cJSON_AddNumberToObject(o, "free_mass_kg", s->free_mass_kg);
    add_group(o, "seconds", s, second_keys, COUNT_OF(second_keys), false);
    return o;
}

sk_result sk_tissue_write_model_stats(const sk_tissue_model *m, const char *path, sk_error *err)
{
    return sk__json_write_file(sk__model_stats_json(m), path, err);
}
