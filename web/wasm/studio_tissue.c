/* The tissue panel's calls (Shigemori & Kawai's fat layer): a character built from its
 * JSON file (the one `shitsukan tissue run --character` reads), its generated rest skin,
 * a BVH motion parsed from text, and the simulation stepped at the character's fixed
 * step, the skin sampled at any later time, as `tissue run` samples its frames. */
#include <stdlib.h>
#include <string.h>

#include "shitsukan/preset.h"
#include "shitsukan/tissue.h"
#include "studio.h"

typedef struct studio_tissue {
    sk_tissue_model *model;
    sk_mesh rest;
    sk_tissue_bvh_motion *motion;
    sk_tissue_sim *sim;
    float *xyz, *ref;
} studio_tissue;

STUDIO_API void studio_tissue_destroy(studio_tissue *t)
{
    if (!t) return;
    sk_tissue_sim_destroy(t->sim);
    sk_tissue_bvh_motion_destroy(t->motion);
    sk_mesh_free(&t->rest);
    sk_tissue_model_destroy(t->model);
    free(t->xyz);
    free(t->ref);
    free(t);
}

/* Binds, resolves and checks a character file's text into a heap desc (NULL on error). */
static sk_tissue_character_desc *character_of(const char *json, sk_error *err)
{
    sk_preset *preset;
    if (sk_preset_parse(&preset, json, strlen(json), "character", err) != SK_OK) return NULL;
    sk_tissue_character_desc *desc = malloc(sizeof *desc);
    if (!desc) {
        sk_preset_free(preset);
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    sk_result r = sk_tissue_character_bind(preset, desc, err);
    sk_preset_free(preset);
    if (r != SK_OK) {
        free(desc);
        return NULL;
    }
    return desc;
}

/* The character's values as the model uses them (every default filled in), as JSON. */
char *studio_tissue_resolved(const char *json, sk_error *err)
{
    sk_tissue_character_desc *desc = character_of(json, err);
    if (!desc) return NULL;
    char *text = sk_schema_to_json(&sk_tissue_character_schema, desc);
    free(desc);
    return text;
}

STUDIO_API studio_tissue *studio_tissue_create(const char *json, sk_error *err)
{
    sk_tissue_character_desc *desc = character_of(json, err);
    if (!desc) return NULL;
    studio_tissue *t = calloc(1, sizeof *t);
    if (!t) {
        free(desc);
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    sk_result r = sk_tissue_model_build(desc, NULL, &t->model, err);
    free(desc);
    if (r == SK_OK) r = sk_tissue_model_rest_skin(t->model, &t->rest, err);
    size_t floats = 3 * (t->rest.vertex_count ? t->rest.vertex_count : 1);
    if (r == SK_OK &&
        (!(t->xyz = malloc(floats * sizeof(float))) || !(t->ref = calloc(floats, sizeof(float)))))
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    if (r != SK_OK) {
        studio_tissue_destroy(t);
        return NULL;
    }
    return t;
}

STUDIO_API int studio_tissue_vertex_count(const studio_tissue *t)
{
    return (int)t->rest.vertex_count;
}
STUDIO_API int studio_tissue_triangle_count(const studio_tissue *t)
{
    return (int)t->rest.triangle_count;
}
STUDIO_API const uint32_t *studio_tissue_indices(const studio_tissue *t) { return t->rest.indices; }
STUDIO_API const float *studio_tissue_rest_positions(const studio_tissue *t)
{
    return t->rest.positions;
}

/* [skin, fat, muscle, bone points, springs, skin triangles, build seconds, step_hz,
 * spacing mm] of the built character. */
STUDIO_API void studio_tissue_stats(const studio_tissue *t, double *out)
{
    sk_tissue_model_stats s = sk_tissue_model_get_stats(t->model);
    out[0] = (double)s.skin_points;
    out[1] = (double)s.fat_points;
    out[2] = (double)s.muscle_points;
    out[3] = (double)s.bone_points;
    out[4] = (double)s.springs;
    out[5] = (double)s.skin_triangles;
    out[6] = s.seconds_total;
    out[7] = sk_tissue_model_desc(t->model)->simulation.step_hz;
    out[8] = s.spacing_mm;
}

/* A BVH motion from its text (`name` for messages). */
STUDIO_API sk_bvh *studio_bvh_parse(const char *text, int length, const char *name, sk_error *err)
{
    sk_bvh *bvh = malloc(sizeof *bvh);
    if (!bvh) {
        sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
        return NULL;
    }
    if (sk_bvh_parse(text, (size_t)length, name, bvh, err) != SK_OK) {
        free(bvh);
        return NULL;
    }
    return bvh;
}

STUDIO_API void studio_bvh_destroy(sk_bvh *bvh)
{
    if (!bvh) return;
    sk_bvh_free(bvh);
    free(bvh);
}

/* The motion on the character from time 0 (a new simulation; the motion's root unit is
 * the character's). Returns the motion's duration in seconds, negative on error. */
STUDIO_API double studio_tissue_play(studio_tissue *t, const sk_bvh *bvh, sk_error *err)
{
    sk_tissue_sim_destroy(t->sim);
    t->sim = NULL;
    sk_tissue_bvh_motion_destroy(t->motion);
    t->motion = NULL;
    if (sk_tissue_bvh_motion_create(t->model, bvh, 0.0, &t->motion, err) != SK_OK) return -1.0;
    sk_tissue_motion motion = sk_tissue_bvh_motion_get(t->motion);
    if (sk_tissue_sim_create(t->model, &motion, &t->sim, err) != SK_OK) return -1.0;
    return motion.duration;
}

/* The skin's vertex positions (mm, rest-skin order) at `seconds`, simulating up to it;
 * NULL on error (no motion, or a time already passed). */
STUDIO_API const float *studio_tissue_skin(studio_tissue *t, double seconds, sk_error *err)
{
    if (!t->sim) {
        sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no motion is playing");
        return NULL;
    }
    if (sk_tissue_sim_skin(t->sim, seconds, t->xyz, err) != SK_OK) return NULL;
    return t->xyz;
}

/* Internal steps simulated so far. */
STUDIO_API double studio_tissue_steps(const studio_tissue *t)
{
    return t->sim ? (double)sk_tissue_sim_steps(t->sim) : 0.0;
}

/* Where the bones and muscles alone carry each skin point at the current step (the skin
 * without the fat layer's secondary motion), 3 floats each. */
STUDIO_API const float *studio_tissue_reference(studio_tissue *t)
{
    if (t->sim) sk_tissue_sim_skin_reference(t->sim, t->ref);
    return t->ref;
}
