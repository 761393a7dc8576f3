/* The glTF reader's checks of the scene objects (glTF 2.0 sec. 3.5-3.11): node hierarchy
 * (one parent each, no loops, TRS or a decomposable matrix), meshes (attribute formats,
 * equal counts, indices in range, morph targets), skins (joints, inverse bind matrices,
 * joint indices of the skinned meshes in range), animations (samplers' key times strictly
 * increasing, output counts and formats by path) and the material / texture / image
 * references. Everything the query functions hand out is checked here. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/gltf_doc_internal.h"
#include "formats/gltf_internal.h"

sk_result sk__gltf_read_objects(sk_gltf_doc *doc, sk_error *err);

#define TRY(call)                                                                                  \
    do {                                                                                           \
        sk_result r_ = (call);                                                                     \
        if (r_ != SK_OK) return r_;                                                                \
    } while (0)

static sk_result object_at(const cJSON *item, const char *where, sk_error *err)
{
    return cJSON_IsObject(item) ? SK_OK
                                : sk_fail(err, SK_ERROR_PARSE, "%s: must be an object", where);
}

/* ----------------------------------------------------------------- meshes */

static bool numbered(const char *name, const char *prefix)
{
    size_t n = strlen(prefix);
    if (strncmp(name, prefix, n) != 0 || !name[n]) return false;
    for (const char *p = name + n; *p; p++)
        if (*p < '0' || *p > '9') return false;
    return true;
}

static bool float_or_unorm(const sk__gltf_accessor *a)
{
    return a->component_type == SK__GLTF_FLOAT ||
           (a->normalized && (a->component_type == SK__GLTF_UNSIGNED_BYTE ||
                              a->component_type == SK__GLTF_UNSIGNED_SHORT));
}

/* The formats of glTF 2.0 sec. 3.7.2.1 (base attributes) and 3.7.2.2 (morph targets). */
static sk_result check_attribute_format(const sk__gltf_accessor *a, const char *name, bool target,
                                        const char *where, sk_error *err)
{
    const char *want = NULL;
    bool vec = a->columns == 0, f = a->component_type == SK__GLTF_FLOAT && vec;
    if (name[0] == '_') return SK_OK; /* application-specific */
    if (strcmp(name, "POSITION") == 0 || strcmp(name, "NORMAL") == 0) {
        if (!(f && a->components == 3)) want = "VEC3 of FLOAT";
    } else if (strcmp(name, "TANGENT") == 0) {
        if (!(f && a->components == (target ? 3 : 4)))
            want = target ? "VEC3 of FLOAT" : "VEC4 of FLOAT";
    } else if (numbered(name, "TEXCOORD_")) {
        if (!(vec && a->components == 2 && (target || float_or_unorm(a))))
            want = "VEC2 of FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT";
    } else if (numbered(name, "COLOR_")) {
        if (!(vec && (a->components == 3 || a->components == 4) && (target || float_or_unorm(a))))
            want = "VEC3 or VEC4 of FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT";
    } else if (numbered(name, "JOINTS_") && !target) {
        if (!(vec && a->components == 4 && !a->normalized &&
              (a->component_type == SK__GLTF_UNSIGNED_BYTE ||
               a->component_type == SK__GLTF_UNSIGNED_SHORT)))
            want = "VEC4 of UNSIGNED_BYTE or UNSIGNED_SHORT";
    } else if (numbered(name, "WEIGHTS_") && !target) {
        if (!(vec && a->components == 4 && float_or_unorm(a)))
            want = "VEC4 of FLOAT or normalized UNSIGNED_BYTE / UNSIGNED_SHORT";
    } else {
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.%s: not a glTF %sattribute (application-specific ones start with '_')",
                       where, name, target ? "morph target " : "");
    }
    if (want)
        return sk_fail(err, SK_ERROR_PARSE, "%s.%s: the accessor must be a %s", where, name, want);
    return SK_OK;
}

/* Checks an attributes object (of a primitive or a morph target): accessors of the right
 * format and one count. *vertex_count: in, the count to match (0 = the first sets it). */
static sk_result check_attributes(const sk_gltf_doc *doc, const cJSON *attrs, const char *where,
                                  bool target, size_t *vertex_count, sk_error *err)
{
    const cJSON *item;
    cJSON_ArrayForEach(item, attrs)
    {
        int index;
        TRY(sk__json_index_item(item, where, item->string, doc->accessor_count, "accessors", &index,
                                err));
        const sk__gltf_accessor *a = &doc->accessors[index];
        TRY(check_attribute_format(a, item->string, target, where, err));
        if (*vertex_count == 0) *vertex_count = a->count;
        if (a->count != *vertex_count)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.%s: accessors[%d] has %zu elements, the others %zu", where,
                           item->string, index, a->count, *vertex_count);
        if (numbered(item->string, "JOINTS_")) {
            char weights[32];
            snprintf(weights, sizeof weights, "WEIGHTS_%s", item->string + 7);
            if (!sk__json_member(attrs, weights))
                return sk_fail(err, SK_ERROR_PARSE, "%s.%s: has no matching %s", where,
                               item->string, weights);
        }
    }
    return SK_OK;
}

static sk_result check_indices(const sk_gltf_doc *doc, int index, size_t vertex_count, int mode,
                               const char *where, sk_error *err)
{
    const sk__gltf_accessor *a = &doc->accessors[index];
    if (a->components != 1 || a->columns != 0 || a->normalized ||
        (a->component_type != SK__GLTF_UNSIGNED_BYTE &&
         a->component_type != SK__GLTF_UNSIGNED_SHORT &&
         a->component_type != SK__GLTF_UNSIGNED_INT))
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.indices: accessors[%d] must be a SCALAR of UNSIGNED_BYTE, "
                       "UNSIGNED_SHORT or UNSIGNED_INT",
                       where, index);
    if (mode == SK__GLTF_TRIANGLES && a->count % 3 != 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s.indices: %zu indices do not make whole triangles",
                       where, a->count);
    for (size_t i = 0; i < a->count; i++) {
        uint32_t v = sk__gltf_accessor_uint(doc, a, i, 0);
        if (v >= vertex_count)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.indices: accessors[%d][%zu] = %u is out of range [0, %zu)", where,
                           index, i, v, vertex_count);
    }
    return SK_OK;
}

/* The largest value of the JOINTS_n attributes of a checked primitive (-1 without). */
static long long max_joint(const sk_gltf_doc *doc, const cJSON *attrs)
{
    long long best = -1;
    const cJSON *attr;
    cJSON_ArrayForEach(attr, attrs)
    {
        if (!numbered(attr->string, "JOINTS_")) continue;
        const sk__gltf_accessor *a = &doc->accessors[(int)attr->valuedouble];
        for (size_t e = 0; e < a->count; e++)
            for (int c = 0; c < 4; c++) {
                long long v = sk__gltf_accessor_uint(doc, a, e, c);
                if (v > best) best = v;
            }
    }
    return best;
}

static sk_result read_primitive(sk_gltf_doc *doc, const cJSON *prim, const char *where,
                                int *target_count, int *indices_out, long long *joint_max,
                                sk_error *err)
{
    TRY(object_at(prim, where, err));
    const cJSON *attrs, *targets, *target;
    long long mode;
    int indices, material;
    TRY(sk__json_object(prim, where, "attributes", true, &attrs, err));
    TRY(sk__json_int(prim, where, "mode", false, 0, 6, SK__GLTF_TRIANGLES, &mode, err));
    TRY(sk__json_index(prim, where, "indices", false, doc->accessor_count, "accessors", &indices,
                       err));
    TRY(sk__json_index(prim, where, "material", false, doc->material_count, "materials", &material,
                       err));
    char at[128];
    snprintf(at, sizeof at, "%s.attributes", where);
    if (!sk__json_member(attrs, "POSITION"))
        return sk_fail(err, SK_ERROR_PARSE, "%s.POSITION: required property is missing", at);
    size_t vertex_count = 0;
    TRY(check_attributes(doc, attrs, at, false, &vertex_count, err));
    if (indices >= 0)
        TRY(check_indices(doc, indices, vertex_count, (int)mode, where, err));
    else if (mode == SK__GLTF_TRIANGLES && vertex_count % 3 != 0)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s: %zu vertices without indices do not make whole triangles", where,
                       vertex_count);
    TRY(sk__json_array(prim, where, "targets", false, 0, &targets, err));
    int t = 0;
    cJSON_ArrayForEach(target, targets)
    {
        snprintf(at, sizeof at, "%s.targets[%d]", where, t);
        TRY(object_at(target, at, err));
        TRY(check_attributes(doc, target, at, true, &vertex_count, err));
        const cJSON *item;
        cJSON_ArrayForEach(item, target) if (!sk__json_member(attrs, item->string)) return sk_fail(
            err, SK_ERROR_PARSE, "%s.%s: the primitive has no %s to displace", at, item->string,
            item->string);
        t++;
    }
    *target_count = t;
    *indices_out = indices;
    long long most = max_joint(doc, attrs);
    if (most > *joint_max) *joint_max = most;
    return SK_OK;
}

static sk_result mesh_item(sk_gltf_doc *doc, const cJSON *m, int i, const char *where, void *user,
                           sk_error *err)
{
    (void)user;
    char at[96];
    const cJSON *prims, *prim;
    TRY(sk__json_array(m, where, "primitives", true, 1, &prims, err));
    int p = 0, first_targets = 0, first_indices = -1;
    long long joint_max = -1;
    cJSON_ArrayForEach(prim, prims)
    {
        int targets = 0, indices = -1;
        snprintf(at, sizeof at, "%s.primitives[%d]", where, p);
        TRY(read_primitive(doc, prim, at, &targets, &indices, &joint_max, err));
        if (p == 0) first_targets = targets, first_indices = indices;
        if (targets != first_targets)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.targets: %d morph targets, primitives[0] has %d", at, targets,
                           first_targets);
        p++;
    }
    if (first_targets > SK__GLTF_MAX_TARGETS)
        return sk_fail(err, SK_ERROR_LIMIT, "%s: %d morph targets exceed the limit of %d", where,
                       first_targets, SK__GLTF_MAX_TARGETS);
    const cJSON *w = sk__json_member(m, "weights");
    if (w && (!cJSON_IsArray(w) || sk__json_count(w) != first_targets))
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.weights: must have one number per morph target (%d)", where,
                       first_targets);
    double weights[SK__GLTF_MAX_TARGETS];
    bool found;
    TRY(sk__json_numbers(m, where, "weights", first_targets, weights, &found, err));
    sk__gltf_doc_mesh *dm = &doc->meshes[i];
    dm->attributes = sk__json_member(prims->child, "attributes");
    dm->targets = sk__json_member(prims->child, "targets");
    dm->target_count = first_targets;
    dm->indices = first_indices;
    dm->max_joint = joint_max;
    return SK_OK;
}

static sk_result read_meshes(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *meshes;
    sk_result r;
    TRY(sk__gltf_items(doc, "meshes", &meshes, &doc->mesh_count, err));
    if (!(doc->meshes =
              sk__gltf_doc_alloc(doc, doc->mesh_count, sizeof *doc->meshes, "meshes", &r, err)))
        return r;
    return sk__gltf_each_item(doc, meshes, "meshes", mesh_item, NULL, err);
}

/* ----------------------------------------------------------------- nodes */

static sk_result read_trs(const cJSON *n, const char *where, sk_gltf_doc_node *out, bool *matrix,
                          sk_error *err)
{
    double m[16];
    bool has_t, has_r, has_s, has_m;
    out->translation[0] = out->translation[1] = out->translation[2] = 0.0;
    out->rotation[0] = out->rotation[1] = out->rotation[2] = 0.0;
    out->rotation[3] = 1.0;
    out->scale[0] = out->scale[1] = out->scale[2] = 1.0;
    double t[3], r[4], s[3];
    TRY(sk__json_numbers(n, where, "translation", 3, t, &has_t, err));
    TRY(sk__json_numbers(n, where, "rotation", 4, r, &has_r, err));
    TRY(sk__json_numbers(n, where, "scale", 3, s, &has_s, err));
    TRY(sk__json_numbers(n, where, "matrix", 16, m, &has_m, err));
    *matrix = has_m;
    if (has_m && (has_t || has_r || has_s))
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.matrix: given together with translation, rotation or scale", where);
    if (has_m) {
        if (!sk__gltf_matrix_to_trs(m, out->translation, out->rotation, out->scale))
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.matrix: not decomposable into translation, rotation and scale",
                           where);
        return SK_OK;
    }
    if (has_t) memcpy(out->translation, t, sizeof t);
    if (has_s) memcpy(out->scale, s, sizeof s);
    if (has_r) {
        double len = sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
        if (!(fabs(len - 1.0) <= SK__GLTF_UNIT_TOLERANCE))
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.rotation: has length %.9g, must be a unit quaternion", where, len);
        memcpy(out->rotation, r, sizeof r);
    }
    return SK_OK;
}

/* A node's children: valid indices, each child's first parent. */
static sk_result children_item(sk_gltf_doc *doc, const cJSON *n, int i, const char *where,
                               void *user, sk_error *err)
{
    (void)user;
    int count;
    TRY(sk__json_indices(n, where, "children", doc->node_count, "nodes", NULL, &count, err));
    int k = 0;
    const cJSON *c;
    cJSON_ArrayForEach(c, sk__json_member(n, "children"))
    {
        int child = (int)c->valuedouble; /* checked above */
        if (child == i)
            return sk_fail(err, SK_ERROR_PARSE, "%s.children[%d]: the node is its own child", where,
                           k);
        if (doc->nodes[child].parent != SK_GLTF_NONE)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.children[%d] = %d: already a child of nodes[%d]", where, k, child,
                           doc->nodes[child].parent);
        doc->nodes[child].parent = i;
        k++;
    }
    return SK_OK;
}

/* Parents from the children lists: one parent each, then no loop (each node is walked up
 * once: a walk stops at a node already known to reach a root). */
static sk_result read_hierarchy(sk_gltf_doc *doc, const cJSON *nodes, sk_error *err)
{
    TRY(sk__gltf_each_item(doc, nodes, "nodes", children_item, NULL, err));
    sk_result r;
    unsigned char *state = /* 0 new, 1 walking, 2 done */
        sk__gltf_doc_alloc(doc, doc->node_count, 1, "nodes", &r, err);
    if (!state) return r;
    for (int start = 0; start < doc->node_count; start++) {
        int v = start;
        while (v != SK_GLTF_NONE && state[v] == 0) {
            state[v] = 1;
            v = doc->nodes[v].parent;
        }
        bool loop = v != SK_GLTF_NONE && state[v] == 1;
        for (v = start; v != SK_GLTF_NONE && state[v] == 1; v = doc->nodes[v].parent) state[v] = 2;
        if (loop) {
            free(state);
            return sk_fail(err, SK_ERROR_PARSE, "nodes[%d]: is part of a loop of children", start);
        }
    }
    free(state);
    return SK_OK;
}

static sk_result node_item(sk_gltf_doc *doc, const cJSON *n, int i, const char *where, void *user,
                           sk_error *err)
{
    (void)user;
    sk_gltf_doc_node *dn = &doc->nodes[i];
    dn->parent = SK_GLTF_NONE;
    TRY(sk__json_string(n, where, "name", false, &dn->name, err));
    if (!dn->name) dn->name = "";
    TRY(sk__json_index(n, where, "mesh", false, doc->mesh_count, "meshes", &dn->mesh, err));
    TRY(sk__json_index(n, where, "skin", false, doc->skin_count, "skins", &dn->skin, err));
    if (dn->skin >= 0 && dn->mesh < 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s.skin: given without a mesh", where);
    return read_trs(n, where, dn, &doc->node_matrix[i], err);
}

static sk_result read_nodes(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *nodes;
    sk_result r;
    TRY(sk__gltf_items(doc, "nodes", &nodes, &doc->node_count, err));
    if (!(doc->nodes =
              sk__gltf_doc_alloc(doc, doc->node_count, sizeof *doc->nodes, "nodes", &r, err)) ||
        !(doc->node_matrix =
              sk__gltf_doc_alloc(doc, doc->node_count, sizeof *doc->node_matrix, "nodes", &r, err)))
        return r;
    TRY(sk__gltf_each_item(doc, nodes, "nodes", node_item, NULL, err));
    return read_hierarchy(doc, nodes, err);
}

/* ----------------------------------------------------------------- skins */

static sk_result skin_item(sk_gltf_doc *doc, const cJSON *s, int i, const char *where, void *user,
                           sk_error *err)
{
    (void)user;
    sk__gltf_doc_skin *ds = &doc->skins[i];
    int skeleton;
    sk_result r;
    TRY(sk__json_indices(s, where, "joints", doc->node_count, "nodes", NULL, &ds->joint_count,
                         err));
    if (ds->joint_count < 1)
        return sk_fail(err, SK_ERROR_PARSE, "%s.joints: must have at least 1 item", where);
    if (!(ds->joints = sk__gltf_doc_alloc(doc, ds->joint_count, sizeof(int), where, &r, err)))
        return r;
    TRY(sk__json_indices(s, where, "joints", doc->node_count, "nodes", ds->joints, &ds->joint_count,
                         err));
    TRY(sk__json_index(s, where, "skeleton", false, doc->node_count, "nodes", &skeleton, err));
    TRY(sk__json_index(s, where, "inverseBindMatrices", false, doc->accessor_count, "accessors",
                       &ds->inverse_bind, err));
    if (ds->inverse_bind < 0) return SK_OK;
    const sk__gltf_accessor *a = &doc->accessors[ds->inverse_bind];
    if (a->components != 16 || a->component_type != SK__GLTF_FLOAT)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.inverseBindMatrices: accessors[%d] must be a MAT4 of FLOAT", where,
                       ds->inverse_bind);
    if (a->count < (size_t)ds->joint_count)
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.inverseBindMatrices: accessors[%d] has %zu matrices for %d joints",
                       where, ds->inverse_bind, a->count, ds->joint_count);
    return SK_OK;
}

static sk_result read_skins(sk_gltf_doc *doc, const cJSON *skins, sk_error *err)
{
    TRY(sk__gltf_each_item(doc, skins, "skins", skin_item, NULL, err));
    /* the joint indices of every skinned mesh stay within its skin */
    for (int n = 0; n < doc->node_count; n++) {
        const sk_gltf_doc_node *dn = &doc->nodes[n];
        if (dn->skin < 0) continue;
        long long most = doc->meshes[dn->mesh].max_joint;
        if (most >= doc->skins[dn->skin].joint_count)
            return sk_fail(err, SK_ERROR_PARSE,
                           "nodes[%d]: meshes[%d] uses joint %lld, skins[%d] has %d joints", n,
                           dn->mesh, most, dn->skin, doc->skins[dn->skin].joint_count);
    }
    return SK_OK;
}

/* ------------------------------------------------------------- animations */

static sk_result check_times(const sk_gltf_doc *doc, int index, const char *where, sk_error *err)
{
    const sk__gltf_accessor *a = &doc->accessors[index];
    if (a->components != 1 || a->columns != 0 || a->component_type != SK__GLTF_FLOAT)
        return sk_fail(err, SK_ERROR_PARSE, "%s.input: accessors[%d] must be a SCALAR of FLOAT",
                       where, index);
    if (!a->has_bounds)
        return sk_fail(err, SK_ERROR_PARSE, "%s.input: accessors[%d] must have min and max", where,
                       index);
    float previous = 0.0f;
    for (size_t k = 0; k < a->count; k++) {
        float t = sk__gltf_accessor_value(doc, a, k, 0);
        if (!isfinite(t) || t < 0.0f)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s.input: key time %zu = %g is not finite and >= 0", where, k,
                           (double)t);
        if (k > 0 && !(t > previous))
            return sk_fail(err, SK_ERROR_PARSE, "%s.input: key time %zu = %.9g is not after %.9g",
                           where, k, (double)t, (double)previous);
        previous = t;
    }
    return SK_OK;
}

static sk_result read_sampler(const sk_gltf_doc *doc, const cJSON *sampler, const char *where,
                              int *input, int *output, sk_gltf_interpolation *interpolation,
                              sk_error *err)
{
    TRY(object_at(sampler, where, err));
    const char *interp;
    TRY(sk__json_index(sampler, where, "input", true, doc->accessor_count, "accessors", input,
                       err));
    TRY(sk__json_index(sampler, where, "output", true, doc->accessor_count, "accessors", output,
                       err));
    TRY(sk__json_string(sampler, where, "interpolation", false, &interp, err));
    if (!interp || strcmp(interp, "LINEAR") == 0)
        *interpolation = SK_GLTF_INTERPOLATION_LINEAR;
    else if (strcmp(interp, "STEP") == 0)
        *interpolation = SK_GLTF_INTERPOLATION_STEP;
    else if (strcmp(interp, "CUBICSPLINE") == 0)
        return sk_fail(err, SK_ERROR_UNSUPPORTED,
                       "%s.interpolation = \"CUBICSPLINE\" is not supported", where);
    else
        return sk_fail(err, SK_ERROR_PARSE,
                       "%s.interpolation = \"%s\" is not LINEAR, STEP or CUBICSPLINE", where,
                       interp);
    return check_times(doc, *input, where, err);
}

/* The output accessor's format and count for the channel's path (sec. 3.11.2). */
static sk_result check_output(const sk_gltf_doc *doc, const sk_gltf_doc_channel *c,
                              const char *where, sk_error *err)
{
    const sk__gltf_accessor *in = &doc->accessors[c->input_accessor],
                            *out = &doc->accessors[c->output_accessor];
    size_t per_key = 1;
    bool ok = out->columns == 0;
    switch (c->path) {
    case SK_GLTF_PATH_TRANSLATION:
    case SK_GLTF_PATH_SCALE:
        ok = ok && out->components == 3 && out->component_type == SK__GLTF_FLOAT;
        break;
    case SK_GLTF_PATH_ROTATION:
        ok = ok && out->components == 4 &&
             (out->component_type == SK__GLTF_FLOAT || out->normalized);
        break;
    case SK_GLTF_PATH_WEIGHTS: {
        int mesh = c->node >= 0 ? doc->nodes[c->node].mesh : -1;
        if (mesh < 0 || doc->meshes[mesh].target_count == 0)
            return sk_fail(err, SK_ERROR_PARSE,
                           "%s: path \"weights\" on a node without morph targets", where);
        per_key = (size_t)doc->meshes[mesh].target_count;
        ok = ok && out->components == 1 &&
             (out->component_type == SK__GLTF_FLOAT || out->normalized);
        break;
    }
    }
    if (!ok)
        return sk_fail(err, SK_ERROR_PARSE, "%s: accessors[%d] has the wrong format for its path",
                       where, c->output_accessor);
    if (out->count / per_key != in->count || out->count % per_key != 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s: accessors[%d] has %zu elements, %zu keys need %zu",
                       where, c->output_accessor, out->count, in->count, in->count * per_key);
    return SK_OK;
}

static int compare_targets(const void *a, const void *b)
{
    const long long *x = a, *y = b;
    return *x < *y ? -1 : *x > *y;
}

static sk_result read_channels(sk_gltf_doc *doc, const cJSON *anim, const char *where,
                               sk__gltf_doc_animation *da, sk_error *err)
{
    static const char *const paths[4] = {"translation", "rotation", "scale", "weights"};
    const cJSON *channels, *samplers, *c;
    TRY(sk__json_array(anim, where, "channels", true, 1, &channels, err));
    TRY(sk__json_array(anim, where, "samplers", true, 1, &samplers, err));
    int sampler_count = sk__json_count(samplers);
    da->channel_count = sk__json_count(channels);
    sk_result r;
    if (!(da->channels =
              sk__gltf_doc_alloc(doc, da->channel_count, sizeof *da->channels, where, &r, err)))
        return r;
    long long *keys = sk__gltf_doc_alloc(doc, da->channel_count, sizeof *keys, where, &r, err);
    const cJSON **sampler_items =
        keys ? sk__gltf_doc_alloc(doc, sampler_count, sizeof *sampler_items, where, &r, err) : NULL;
    if (!sampler_items) {
        free(keys);
        return r;
    }
    int q = 0;
    const cJSON *s;
    cJSON_ArrayForEach(s, samplers) sampler_items[q++] = s;
    int k = 0;
    cJSON_ArrayForEach(c, channels)
    {
        char at[96], sat[96];
        snprintf(at, sizeof at, "%s.channels[%d]", where, k);
        sk_gltf_doc_channel *ch = &da->channels[k];
        const cJSON *target;
        const char *path;
        int sampler;
        if ((r = object_at(c, at, err)) ||
            (r = sk__json_index(c, at, "sampler", true, sampler_count, "the samplers", &sampler,
                                err)) ||
            (r = sk__json_object(c, at, "target", true, &target, err)))
            break;
        snprintf(sat, sizeof sat, "%s.target", at);
        if ((r = sk__json_index(target, sat, "node", false, doc->node_count, "nodes", &ch->node,
                                err)) ||
            (r = sk__json_string(target, sat, "path", true, &path, err)))
            break;
        int p = 0;
        while (p < 4 && strcmp(path, paths[p]) != 0) p++;
        if (p == 4) {
            r = sk_fail(err, SK_ERROR_UNSUPPORTED,
                        "%s.path = \"%s\" is not translation, rotation, scale or weights", sat,
                        path);
            break;
        }
        ch->path = (sk_gltf_path)p;
        if (ch->path != SK_GLTF_PATH_WEIGHTS && ch->node >= 0 && doc->node_matrix[ch->node]) {
            r = sk_fail(err, SK_ERROR_PARSE,
                        "%s.node = %d: a node given as a matrix cannot have its %s animated", sat,
                        ch->node, path);
            break;
        }
        s = sampler_items[sampler];
        snprintf(sat, sizeof sat, "%s.samplers[%d]", where, sampler);
        if ((r = read_sampler(doc, s, sat, &ch->input_accessor, &ch->output_accessor,
                              &ch->interpolation, err)) ||
            (r = check_output(doc, ch, sat, err)))
            break;
        keys[k] = (long long)(ch->node + 1) * 4 + p;
        k++;
    }
    if (r == SK_OK) {
        /* the same node and path twice in one animation is an error of glTF 2.0 */
        qsort(keys, (size_t)da->channel_count, sizeof *keys, compare_targets);
        for (int i = 1; i < da->channel_count && r == SK_OK; i++)
            if (keys[i] == keys[i - 1] && keys[i] >= 4)
                r = sk_fail(err, SK_ERROR_PARSE, "%s: two channels target nodes[%lld].%s", where,
                            keys[i] / 4 - 1, paths[keys[i] % 4]);
    }
    free(keys);
    free(sampler_items);
    return r;
}

static sk_result animation_item(sk_gltf_doc *doc, const cJSON *a, int i, const char *where,
                                void *user, sk_error *err)
{
    (void)user;
    return read_channels(doc, a, where, &doc->animations[i], err);
}

static sk_result read_animations(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *anims;
    sk_result r;
    TRY(sk__gltf_items(doc, "animations", &anims, &doc->animation_count, err));
    if (!(doc->animations = sk__gltf_doc_alloc(doc, doc->animation_count, sizeof *doc->animations,
                                               "animations", &r, err)))
        return r;
    return sk__gltf_each_item(doc, anims, "animations", animation_item, NULL, err);
}

/* ------------------------------------------------ materials, textures, images */

static sk_result check_texture_ref(const sk_gltf_doc *doc, const cJSON *owner, const char *where,
                                   const char *key, sk_error *err)
{
    const cJSON *info;
    int index;
    TRY(sk__json_object(owner, where, key, false, &info, err));
    if (!info) return SK_OK;
    char at[96];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return sk__json_index(info, at, "index", true, doc->texture_count, "textures", &index, err);
}

static sk_result image_item(sk_gltf_doc *doc, const cJSON *o, int i, const char *where, void *user,
                            sk_error *err)
{
    (void)i, (void)user;
    int view;
    const char *uri, *mime;
    TRY(sk__json_index(o, where, "bufferView", false, doc->view_count, "bufferViews", &view, err));
    TRY(sk__json_string(o, where, "uri", false, &uri, err));
    TRY(sk__json_string(o, where, "mimeType", view >= 0, &mime, err));
    if ((view >= 0) == (uri != NULL))
        return sk_fail(err, SK_ERROR_PARSE, "%s: needs exactly one of bufferView and uri", where);
    return SK_OK;
}

static sk_result texture_item(sk_gltf_doc *doc, const cJSON *o, int i, const char *where,
                              void *user, sk_error *err)
{
    (void)i, (void)user;
    int source;
    return sk__json_index(o, where, "source", false, doc->image_count, "images", &source, err);
}

static sk_result material_item(sk_gltf_doc *doc, const cJSON *o, int i, const char *where,
                               void *user, sk_error *err)
{
    (void)i, (void)user;
    char at[64];
    const cJSON *pbr;
    TRY(sk__json_object(o, where, "pbrMetallicRoughness", false, &pbr, err));
    snprintf(at, sizeof at, "%s.pbrMetallicRoughness", where);
    TRY(check_texture_ref(doc, pbr, at, "baseColorTexture", err));
    TRY(check_texture_ref(doc, pbr, at, "metallicRoughnessTexture", err));
    TRY(check_texture_ref(doc, o, where, "normalTexture", err));
    TRY(check_texture_ref(doc, o, where, "occlusionTexture", err));
    return check_texture_ref(doc, o, where, "emissiveTexture", err);
}

static sk_result read_materials(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *images, *textures, *materials;
    TRY(sk__gltf_items(doc, "images", &images, &doc->image_count, err));
    TRY(sk__gltf_items(doc, "textures", &textures, &doc->texture_count, err));
    TRY(sk__gltf_items(doc, "materials", &materials, &doc->material_count, err));
    TRY(sk__gltf_each_item(doc, images, "images", image_item, NULL, err));
    TRY(sk__gltf_each_item(doc, textures, "textures", texture_item, NULL, err));
    return sk__gltf_each_item(doc, materials, "materials", material_item, NULL, err);
}

/* A scene's nodes: roots only. */
static sk_result scene_item(sk_gltf_doc *doc, const cJSON *s, int i, const char *where, void *user,
                            sk_error *err)
{
    (void)i, (void)user;
    int count;
    TRY(sk__json_indices(s, where, "nodes", doc->node_count, "nodes", NULL, &count, err));
    int k = 0;
    const cJSON *n;
    cJSON_ArrayForEach(n, sk__json_member(s, "nodes"))
    {
        int node = (int)n->valuedouble; /* checked above */
        if (doc->nodes[node].parent != SK_GLTF_NONE)
            return sk_fail(err, SK_ERROR_PARSE, "%s.nodes[%d] = %d: not a root node", where, k,
                           node);
        k++;
    }
    return SK_OK;
}

static sk_result read_scenes(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *scenes;
    int scene_count, scene;
    TRY(sk__gltf_items(doc, "scenes", &scenes, &scene_count, err));
    TRY(sk__json_index(doc->json, "", "scene", false, scene_count, "scenes", &scene, err));
    return sk__gltf_each_item(doc, scenes, "scenes", scene_item, NULL, err);
}

sk_result sk__gltf_read_objects(sk_gltf_doc *doc, sk_error *err)
{
    const cJSON *skins;
    sk_result r;
    /* materials first (primitives refer to them), skins are counted before the nodes
       that name them and checked after, when the meshes' joint indices are known */
    TRY(read_materials(doc, err));
    TRY(read_meshes(doc, err));
    TRY(sk__gltf_items(doc, "skins", &skins, &doc->skin_count, err));
    if (!(doc->skins =
              sk__gltf_doc_alloc(doc, doc->skin_count, sizeof *doc->skins, "skins", &r, err)))
        return r;
    TRY(read_nodes(doc, err));
    TRY(read_skins(doc, skins, err));
    TRY(read_animations(doc, err));
    return read_scenes(doc, err);
}
