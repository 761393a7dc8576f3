/* A tissue character (Shigemori & Kawai sec. 2): defaults of the desc, the checks the
 * schema cannot state (references between joints, bones, muscles and fat regions; one
 * root; no cycles), and loading from JSON. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "shitsukan/io.h"
#include "models/tissue/tissue_internal.h"

int sk__joint_find(const sk_tissue_character_desc *d, const char *name)
{
    for (int i = 0; i < d->joint_count; i++)
        if (strcmp(d->joints[i].name, name) == 0) return i;
    return -1;
}

int sk__bone_find(const sk_tissue_character_desc *d, const char *name)
{
    for (int i = 0; i < d->bone_count; i++)
        if (strcmp(d->bones[i].name, name) == 0) return i;
    return -1;
}

int sk__muscle_find(const sk_tissue_character_desc *d, const char *name)
{
    for (int i = 0; i < d->muscle_count; i++)
        if (strcmp(d->muscles[i].name, name) == 0) return i;
    return -1;
}

static float or_default(float v, float fallback) { return v == 0.0f ? fallback : v; }

void sk_tissue_character_desc_resolve(sk_tissue_character_desc *d)
{
    /* the defaults sk_tissue_character_schema states, then those computed from other keys */
    sk_schema_apply_defaults(&sk_tissue_character_schema, d);
    for (int i = 0; i < d->bone_count; i++) {
        sk_tissue_bone_desc *b = &d->bones[i];
        b->end_length_mm = or_default(b->end_length_mm, b->radius_mm);
    }
    for (int i = 0; i < d->fat_count; i++) {
        sk_tissue_fat_desc *f = &d->fat[i];
        if (f->from == 0.0f && f->to == 0.0f) f->to = 1.0f;
    }
    sk_tissue_skin_desc *s = &d->skin;
    s->dilation_radius_mm = or_default(s->dilation_radius_mm, 1.5f * s->spacing_mm);
    sk_tissue_material_desc *m = &d->material;
    m->anchor_stiffness = or_default(m->anchor_stiffness, m->fat_stiffness);
    m->skin_stiffness = or_default(m->skin_stiffness, 5.0f * m->fat_stiffness);
    m->tether_stiffness = or_default(m->tether_stiffness, 0.4f * m->fat_stiffness);
}

/* "a, b, c" of `count` names `stride` bytes apart, cut with ", ..." to fit `size`. */
static void list_names(char *buf, size_t size, int count, const char *first, size_t stride)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < count; i++) {
        const char *name = first + stride * (size_t)i;
        size_t need = strlen(name) + (i ? 2 : 0);
        if (used + need + 6 > size) { /* room is always left for ", ..." */
            snprintf(buf + used, size - used, "%s...", i ? ", " : "");
            return;
        }
        snprintf(buf + used, size - used, "%s%s", i ? ", " : "", name);
        used += need;
    }
}

static sk_result not_a(sk_error *err, const char *path, const char *value, const char *what,
                       const sk_tissue_character_desc *d)
{
    char names[200];
    if (strcmp(what, "joint") == 0)
        list_names(names, sizeof names, d->joint_count, d->joints[0].name, sizeof d->joints[0]);
    else if (strcmp(what, "bone") == 0)
        list_names(names, sizeof names, d->bone_count, d->bones[0].name, sizeof d->bones[0]);
    else
        list_names(names, sizeof names, d->muscle_count, d->muscles[0].name, sizeof d->muscles[0]);
    return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s = \"%s\" is not a %s (%ss: %s)", path, value,
                   what, what, names);
}

static sk_result check_name(sk_error *err, const char *path, const char *name)
{
    if (!name[0])
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s is missing (a non-empty name)", path);
    return SK_OK;
}

static sk_result check_unique(sk_error *err, const char *what, int count, const char *first,
                              size_t stride)
{
    for (int i = 0; i < count; i++)
        for (int k = 0; k < i; k++)
            if (strcmp(first + stride * (size_t)i, first + stride * (size_t)k) == 0)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "%s[%d].name = \"%s\" is also %s[%d]'s", what, i,
                               first + stride * (size_t)i, what, k);
    return SK_OK;
}

static bool is_zero3(const float v[3]) { return v[0] == 0.0f && v[1] == 0.0f && v[2] == 0.0f; }

static sk_result check_joints(const sk_tissue_character_desc *d, sk_error *err)
{
    char path[96];
    if (d->joint_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joints: a character needs at least one joint");
    sk_result r =
        check_unique(err, "joints", d->joint_count, d->joints[0].name, sizeof d->joints[0]);
    if (r != SK_OK) return r;
    int roots = 0;
    for (int i = 0; i < d->joint_count; i++) {
        snprintf(path, sizeof path, "joints[%d].name", i);
        if ((r = check_name(err, path, d->joints[i].name)) != SK_OK) return r;
        if (!d->joints[i].parent[0]) {
            if (roots++)
                return sk_fail(
                    err, SK_ERROR_INVALID_ARGUMENT,
                    "joints[%d] (\"%s\") has no parent, but the skeleton already has a root", i,
                    d->joints[i].name);
            continue;
        }
        snprintf(path, sizeof path, "joints[%d].parent", i);
        if (sk__joint_find(d, d->joints[i].parent) < 0)
            return not_a(err, path, d->joints[i].parent, "joint", d);
    }
    if (roots == 0)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "joints: no root (one joint must have no parent)");
    /* no cycles: every chain of parents reaches the root within joint_count steps */
    for (int i = 0; i < d->joint_count; i++) {
        int j = i, steps = 0;
        while (d->joints[j].parent[0] && steps++ <= d->joint_count)
            j = sk__joint_find(d, d->joints[j].parent);
        if (steps > d->joint_count)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "joints[%d] (\"%s\"): its parents form a cycle", i, d->joints[i].name);
    }
    return SK_OK;
}

static sk_result check_attachment(const sk_tissue_character_desc *d,
                                  const sk_tissue_attachment_desc *a, const char *path,
                                  sk_error *err)
{
    char p[128];
    snprintf(p, sizeof p, "%s.bone", path);
    if (sk__bone_find(d, a->bone) < 0) return not_a(err, p, a->bone, "bone", d);
    return SK_OK;
}

static sk_result check_body(const sk_tissue_character_desc *d, sk_error *err)
{
    char path[96];
    sk_result r;
    if (d->bone_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "bones: a character needs at least one bone");
    if ((r = check_unique(err, "bones", d->bone_count, d->bones[0].name, sizeof d->bones[0])) !=
        SK_OK)
        return r;
    for (int i = 0; i < d->bone_count; i++) {
        const sk_tissue_bone_desc *b = &d->bones[i];
        snprintf(path, sizeof path, "bones[%d].name", i);
        if ((r = check_name(err, path, b->name)) != SK_OK) return r;
        snprintf(path, sizeof path, "bones[%d].joint", i);
        if (sk__joint_find(d, b->joint) < 0) return not_a(err, path, b->joint, "joint", d);
        snprintf(path, sizeof path, "bones[%d].end", i);
        if (b->end[0] && sk__joint_find(d, b->end) < 0) return not_a(err, path, b->end, "joint", d);
    }
    if ((r = check_unique(err, "muscles", d->muscle_count, d->muscles[0].name,
                          sizeof d->muscles[0])) != SK_OK)
        return r;
    for (int i = 0; i < d->muscle_count; i++) {
        const sk_tissue_muscle_desc *m = &d->muscles[i];
        snprintf(path, sizeof path, "muscles[%d].name", i);
        if ((r = check_name(err, path, m->name)) != SK_OK) return r;
        if (sk__bone_find(d, m->name) >= 0)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "muscles[%d].name = \"%s\" is also a bone's", i, m->name);
        snprintf(path, sizeof path, "muscles[%d].origin", i);
        if ((r = check_attachment(d, &m->origin, path, err)) != SK_OK) return r;
        snprintf(path, sizeof path, "muscles[%d].insertion", i);
        if ((r = check_attachment(d, &m->insertion, path, err)) != SK_OK) return r;
    }
    return SK_OK;
}

static sk_result check_extras(const sk_tissue_character_desc *d, sk_error *err)
{
    char path[96];
    sk_result r;
    for (int i = 0; i < d->fat_count; i++) {
        const sk_tissue_fat_desc *f = &d->fat[i];
        snprintf(path, sizeof path, "fat[%d].around", i);
        if (sk__bone_find(d, f->around) < 0 && sk__muscle_find(d, f->around) < 0) {
            if (d->muscle_count == 0) return not_a(err, path, f->around, "bone", d);
            char bones[200], muscles[200];
            list_names(bones, sizeof bones, d->bone_count, d->bones[0].name, sizeof d->bones[0]);
            list_names(muscles, sizeof muscles, d->muscle_count, d->muscles[0].name,
                       sizeof d->muscles[0]);
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s = \"%s\" is neither a bone (%s) nor a muscle (%s)", path, f->around,
                           bones, muscles);
        }
        if (!(f->from < f->to))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "fat[%d]: from = %g must be less than to = %g", i, f->from, f->to);
    }
    for (int i = 0; i < d->joint_map_count; i++) {
        snprintf(path, sizeof path, "joint_map[%d].motion", i);
        if ((r = check_name(err, path, d->joint_map[i].motion)) != SK_OK) return r;
        snprintf(path, sizeof path, "joint_map[%d].joint", i);
        if (sk__joint_find(d, d->joint_map[i].joint) < 0)
            return not_a(err, path, d->joint_map[i].joint, "joint", d);
    }
    if ((r = check_unique(err, "tracked", d->tracked_count, d->tracked[0].name,
                          sizeof d->tracked[0])) != SK_OK)
        return r;
    for (int i = 0; i < d->tracked_count; i++) {
        snprintf(path, sizeof path, "tracked[%d].name", i);
        if ((r = check_name(err, path, d->tracked[i].name)) != SK_OK) return r;
        snprintf(path, sizeof path, "tracked[%d].bone", i);
        if (sk__bone_find(d, d->tracked[i].bone) < 0)
            return not_a(err, path, d->tracked[i].bone, "bone", d);
        if (is_zero3(d->tracked[i].direction))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "tracked[%d].direction must not be zero",
                           i);
    }
    return SK_OK;
}

/* The rules between keys of the skin (sec. 4) beyond the schema's ranges. */
static sk_result check_skin_rules(const sk_tissue_character_desc *d, sk_error *err)
{
    const sk_tissue_skin_desc *s = &d->skin;
    sk_result r;
    if ((r = sk_check_range_f(err, "skin.dilation_radius_mm", s->dilation_radius_mm, s->spacing_mm,
                              10.0 * s->spacing_mm)) != SK_OK)
        return r;
    if (!(s->threshold > 0.0f && s->threshold < 1.0f))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin.threshold = %g is out of range (0, 1)",
                       s->threshold);
    if (s->neighbourhood != 18 && s->neighbourhood != 26)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "skin.neighbourhood = %d must be 18 or 26",
                       s->neighbourhood);
    return SK_OK;
}

sk_result sk_tissue_character_desc_validate(const sk_tissue_character_desc *d, sk_error *err)
{
    if (!d) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "character desc is NULL");
    sk_result r = check_joints(d, err);
    if (r == SK_OK) r = check_body(d, err);
    if (r == SK_OK) r = check_extras(d, err);
    /* every range, as sk_tissue_character_schema states it */
    if (r == SK_OK) r = sk_schema_check(&sk_tissue_character_schema, d, "", err);
    if (r == SK_OK) r = check_skin_rules(d, err);
    return r;
}
