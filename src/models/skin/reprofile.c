/* The parameters of a skin that leave its cells where they are: each level's section
 * profile and roundness (Ishii et al. 1991, sec. 3.2.1 (2), parameters 5 and 6), the
 * normal model, the pores and the shading; set when a skin is built, and given anew to a
 * built skin by sk_skin_reprofile (an edit of them then costs a render, not a build). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/skin/skin_internal.h"

void sk__level_profile_setup(sk_skin *skin, int k)
{
    const sk_skin_level *d = &skin->desc.levels[k];
    sk__level *lv = &skin->levels[k];
    lv->roundness = d->roundness;
    /* profile z is in tenths of the nominal cell radius (spacing / 2) */
    lv->z_scale = d->spacing_mm / 20.0f;
    sk__profile *p = &lv->profile;
    p->segment_count = d->segment_count;
    p->z_min = INFINITY, p->z_max = -INFINITY;
    for (int s = 0; s < d->segment_count; s++)
        for (int i = 0; i < 4; i++) {
            p->x[s][i] = d->segments[s].points[i][0];
            p->z[s][i] = d->segments[s].points[i][1];
            p->z_min = fminf(p->z_min, p->z[s][i]);
            p->z_max = fmaxf(p->z_max, p->z[s][i]);
        }
    p->g_min = 1.0f - d->roundness;
    sk__profile_prepare(p);
}

void sk__shading_setup(sk_skin *skin)
{
    const sk_skin_shading *sh = &skin->desc.shading;
    double el = sh->light_elevation, az = sh->light_azimuth;
    /* azimuth 0 = light from +y (top of the image), counter-clockwise */
    double lx = -sin(az) * cos(el), ly = cos(az) * cos(el), lz = sin(el);
    skin->light[0] = (float)lx, skin->light[1] = (float)ly, skin->light[2] = (float)lz;
    double hx = lx, hy = ly, hz = lz + 1.0, hl = sqrt(hx * hx + hy * hy + hz * hz);
    skin->half[0] = (float)(hx / hl), skin->half[1] = (float)(hy / hl),
    skin->half[2] = (float)(hz / hl);
    for (int i = 0; i < 3; i++) skin->albedo[i] = sh->albedo[i];
    skin->sun = sh->sun_fraction;
    skin->sky = 1.0f - sh->sun_fraction;
    skin->spec = sh->no_specular ? 0.0f : sh->specular;
    skin->shininess = sh->shininess;
    skin->shininess_int = sh->shininess == floorf(sh->shininess) ? (int)sh->shininess : 0;
}

void sk__height_range(sk_skin *skin)
{
    float lo = 0, hi = 0;
    for (int k = 0; k < skin->level_count; k++) {
        const sk__level *lv = &skin->levels[k];
        lo += lv->profile.z_min * lv->z_scale;
        hi += lv->profile.z_max * lv->z_scale;
    }
    /* the profiles stay within their control points' z (a Bezier curve lies in their
       hull); pores dig below, deeper where they overlap */
    lo -= sk__pores_deepest(skin);
    skin->height_min = lo;
    skin->height_max = hi > lo ? hi : lo + 1e-6f;
}

/* Bit for bit, so that equal keys give the skin sk_skin_create would build (a value and
 * its negative zero could round differently in the lattice and the stretch). */
#define SAME(a, b) (memcmp(&(a), &(b), sizeof(a)) == 0)

/* The first key that places cells and differs between two resolved descs, as its preset
 * key path (written to `name`), or NULL when the cells are the same. */
static const char *cell_key_differing(const sk_skin_desc *a, const sk_skin_desc *b, char name[64])
{
    if (!SAME(a->seed, b->seed)) return "seed";
    if (!SAME(a->size_mm, b->size_mm)) return "size_mm";
    if (!SAME(a->aperiodic, b->aperiodic)) return "aperiodic";
    if (!SAME(a->level_count, b->level_count)) return "levels (their count)";
    for (int k = 0; k < a->level_count; k++) {
        const sk_skin_level *p = &a->levels[k], *q = &b->levels[k];
        const char *key = NULL;
        if (!SAME(p->layout, q->layout))
            key = "layout";
        else if (!SAME(p->jitter, q->jitter))
            key = "jitter";
        else if (!SAME(p->jitter_rate, q->jitter_rate))
            key = "jitter_rate";
        else if (!SAME(p->spacing_mm, q->spacing_mm))
            key = "spacing_mm";
        else if (!SAME(p->perturb_rate, q->perturb_rate))
            key = "perturb_rate";
        else if (!SAME(p->perturb_decay, q->perturb_decay))
            key = "perturb_decay";
        else if (!SAME(p->perturb_depth, q->perturb_depth))
            key = "perturb_depth";
        else if (!SAME(p->stretch, q->stretch))
            key = "stretch";
        else if (!SAME(p->stretch_angle, q->stretch_angle))
            key = "stretch_angle_deg";
        if (key) {
            snprintf(name, 64, "levels[%d].%s", k, key);
            return name;
        }
    }
    return NULL;
}

/* Pores of one kind are the same when neither kind digs or every key is equal. */
static bool same_pore_kind(const sk_skin_pore_kind *a, const sk_skin_pore_kind *b)
{
    if (a->depth_mm == 0.0f && b->depth_mm == 0.0f) return true;
    return SAME(a->depth_mm, b->depth_mm) && SAME(a->radius_mm, b->radius_mm) &&
           SAME(a->density, b->density);
}

static bool same_pores(const sk_skin_pores *a, const sk_skin_pores *b)
{
    return same_pore_kind(&a->hair, &b->hair) && same_pore_kind(&a->sweat, &b->sweat) &&
           (b->sweat.depth_mm == 0.0f || SAME(a->sweat_level, b->sweat_level));
}

/* The pores placed again on the skin's cells for its desc; on failure the skin keeps
 * the pores it had. */
static sk_result replace_pores(sk_skin *skin, sk_error *err)
{
    sk__pore_grid old = skin->pores;
    memset(&skin->pores, 0, sizeof skin->pores);
    sk_result r = sk__build_pores(skin, err);
    sk__pore_grid *drop = r == SK_OK ? &old : &skin->pores;
    free(drop->start);
    free(drop->near);
    if (r != SK_OK) skin->pores = old;
    return r;
}

/* The relief keys of the cells' levels: section profiles, roundness, the normal model. */
static bool same_relief(const sk_skin_desc *a, const sk_skin_desc *b)
{
    if (!SAME(a->normal_model, b->normal_model)) return false;
    for (int k = 0; k < a->level_count; k++) {
        const sk_skin_level *p = &a->levels[k], *q = &b->levels[k];
        if (!SAME(p->segment_count, q->segment_count) || !SAME(p->roundness, q->roundness))
            return false;
        if (memcmp(p->segments, q->segments, sizeof p->segments[0] * (size_t)p->segment_count))
            return false;
    }
    return true;
}

static bool same_shading(const sk_skin_shading *a, const sk_skin_shading *b)
{
    return SAME(a->light_azimuth, b->light_azimuth) &&
           SAME(a->light_elevation, b->light_elevation) && SAME(a->albedo, b->albedo) &&
           SAME(a->sun_fraction, b->sun_fraction) && SAME(a->specular, b->specular) &&
           SAME(a->shininess, b->shininess) && SAME(a->no_specular, b->no_specular);
}

unsigned sk_skin_desc_changes(const sk_skin_desc *a, const sk_skin_desc *b)
{
    sk_skin_desc ra = sk_skin_desc_resolved(a), rb = sk_skin_desc_resolved(b);
    char name[64];
    if (cell_key_differing(&ra, &rb, name)) return SK_SKIN_CHANGE_CELLS;
    unsigned changes = 0;
    if (!same_relief(&ra, &rb) || !same_pores(&ra.pores, &rb.pores))
        changes |= SK_SKIN_CHANGE_RELIEF;
    if (!same_shading(&ra.shading, &rb.shading)) changes |= SK_SKIN_CHANGE_SHADING;
    return changes;
}

sk_result sk_skin_reprofile(sk_skin *skin, const sk_skin_desc *desc, sk_error *err)
{
    if (!skin) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "sk_skin_reprofile: skin is NULL");
    sk_result r = sk_skin_desc_validate(desc, err);
    if (r != SK_OK) return r;
    sk_skin_desc resolved = sk_skin_desc_resolved(desc);
    r = sk_skin_desc_validate(&resolved, err);
    if (r != SK_OK) return r;
    char name[64];
    const char *key = cell_key_differing(&skin->desc, &resolved, name);
    if (key)
        return sk_fail(err, SK_ERROR_UNSUPPORTED,
                       "%s differs from the built skin's: it places the cells, so the skin "
                       "must be built again (sk_skin_create)",
                       key);
    sk_skin_desc before = skin->desc;
    skin->desc = resolved;
    if (!same_pores(&before.pores, &resolved.pores)) {
        r = replace_pores(skin, err);
        if (r != SK_OK) {
            skin->desc = before;
            return r;
        }
    }
    for (int k = 0; k < skin->level_count; k++) sk__level_profile_setup(skin, k);
    sk__height_range(skin);
    sk__shading_setup(skin);
    return SK_OK;
}
