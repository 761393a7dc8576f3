/* The built model's counts and where its build time went, as JSON (the skin generation of
 * Shigemori & Kawai sec. 4: voxels, dilation, isosurface, classification, springs). */
#include <cjson/cJSON.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/io.h"
#include "tissue/tissue_internal.h"

static void add_count(cJSON *o, const char *key, size_t v) { cJSON_AddNumberToObject(o, key, (double)v); }

cJSON *sk__model_stats_json(const sk_tissue_model *m)
{
    const sk_tissue_model_stats *s = &m->stats;
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON_AddStringToObject(o, "character", m->desc.name);
    cJSON *grid = cJSON_AddArrayToObject(o, "grid");
    for (int k = 0; k < 3; k++) cJSON_AddItemToArray(grid, cJSON_CreateNumber(s->grid[k]));
    cJSON_AddNumberToObject(o, "spacing_mm", s->spacing_mm);
    add_count(o, "tissue_voxels", s->tissue_voxels);
    cJSON *points = cJSON_AddObjectToObject(o, "points");
    add_count(points, "skin", s->skin_points);
    add_count(points, "fat", s->fat_points);
    add_count(points, "muscle", s->muscle_points);
    add_count(points, "bone", s->bone_points);
    add_count(points, "total", s->points);
    cJSON *springs = cJSON_AddObjectToObject(o, "springs");
    add_count(springs, "skin", s->skin_springs);
    add_count(springs, "skin_fat", s->skin_fat_springs);
    add_count(springs, "fat", s->fat_springs);
    add_count(springs, "fat_tissue", s->anchor_springs);
    add_count(springs, "total", s->springs);
    add_count(o, "skin_triangles", s->skin_triangles);
    add_count(o, "removed_cells", s->removed_cells);
    cJSON_AddNumberToObject(o, "free_mass_kg", s->free_mass_kg);
    cJSON *sec = cJSON_AddObjectToObject(o, "seconds");
    cJSON_AddNumberToObject(sec, "voxelise", s->seconds_voxelise);
    cJSON_AddNumberToObject(sec, "fat_regions", s->seconds_fat);
    cJSON_AddNumberToObject(sec, "dilate", s->seconds_dilate);
    cJSON_AddNumberToObject(sec, "extract", s->seconds_extract);
    cJSON_AddNumberToObject(sec, "classify", s->seconds_classify);
    cJSON_AddNumberToObject(sec, "springs", s->seconds_springs);
    cJSON_AddNumberToObject(sec, "total", s->seconds_total);
    return o;
}

sk_result sk__write_json(cJSON *root, const char *path, sk_error *err)
{
    char *text = root ? cJSON_Print(root) : NULL;
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %s", path);
    sk_atomic_file f;
    sk_result r = sk_atomic_file_open(&f, path, err);
    if (r == SK_OK) {
        size_t n = strlen(text);
        if (fwrite(text, 1, n, f.fp) != n || fputc('\n', f.fp) == EOF) {
            sk_atomic_file_abort(&f);
            r = sk_fail(err, SK_ERROR_IO, "%s: write failed", path);
        } else {
            r = sk_atomic_file_commit(&f, err);
        }
    }
    free(text);
    return r;
}

sk_result sk_tissue_write_model_stats(const sk_tissue_model *m, const char *path, sk_error *err)
{
    return sk__write_json(sk__model_stats_json(m), path, err);
}
