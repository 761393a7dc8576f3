/* Calibrated potentials (thesis 3.2.2, eq. 3.17 fitted to samples) as JSON files: the
 * calibrated DOFs, the scale from precision to stiffness units, and per mixture
 * component its weight, relaxed posture (eq. 3.7) and a constraint set (springs K and
 * rows A, W on displacements, b = 0) in the format of the constraint files. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/potential_internal.h"
#include "models/hand/solver_internal.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

/* ---------------------------------------------------------------- write */

static cJSON *row_json(const sk_hand_row *row)
{
    cJSON *o = cJSON_CreateObject();
    if (!o) return NULL;
    cJSON *terms = cJSON_AddObjectToObject(o, "terms");
    for (int t = 0; terms && t < row->term_count; t++)
        cJSON_AddNumberToObject(terms, sk_hand_dof(row->dof[t])->name, row->coeff[t]);
    cJSON_AddNumberToObject(o, "b", row->b * SK_RAD_TO_DEG);
    cJSON_AddNumberToObject(o, "W", row->weight);
    if (row->label[0]) cJSON_AddStringToObject(o, "label", row->label);
    return o;
}

sk_result sk_hand_potential_write_json(const sk_hand_potential *p, const char *source_note,
                                       const char *path, sk_error *err)
{
    sk_hand_skeleton skel;
    sk_result r = sk_hand_skeleton_init(&skel, NULL, err);
    if (r != SK_OK) return r;
    cJSON *root = cJSON_CreateObject();
    if (!root) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    cJSON_AddStringToObject(
        root, "description",
        "Calibrated potential of natural posture: eq. 3.17 fitted to joint-angle samples "
        "(thesis 3.2.2); the energy of each component is the samples' Gaussian");
    if (source_note) cJSON_AddStringToObject(root, "source", source_note);
    cJSON_AddStringToObject(root, "reading",
                            "Each component is a constraint set on displacements from its relaxed "
                            "posture (degrees): springs "
                            "K ('stiffness') and rows A theta + b = 0 with weights W; on the "
                            "calibrated DOFs K + A'WA = scale x "
                            "the inverse covariance (1/rad^2) of the component and b = 0. A solve "
                            "blends the components' "
                            "equilibria by the probability of the pinned values under each "
                            "(mixture weights 'weight').");
    cJSON *dofs = cJSON_AddArrayToObject(root, "dofs");
    for (int a = 0; dofs && a < p->dof_count; a++)
        cJSON_AddItemToArray(dofs, cJSON_CreateString(sk_hand_dof(p->dof[a])->name));
    cJSON_AddNumberToObject(root, "scale", p->scale);
    cJSON_AddNumberToObject(root, "samples", p->sample_count);
    cJSON_AddNumberToObject(root, "prior_strength", p->prior_strength);
    cJSON *comps = cJSON_AddArrayToObject(root, "components");
    for (int m = 0; comps && m < p->component_count; m++) {
        const sk_hand_potential_component *c = &p->component[m];
        cJSON *o = cJSON_CreateObject();
        if (!o) break;
        cJSON_AddItemToArray(comps, o);
        cJSON_AddNumberToObject(o, "weight", c->weight);
        cJSON *relaxed = cJSON_AddObjectToObject(o, "relaxed_deg");
        for (int a = 0; relaxed && a < p->dof_count; a++)
            cJSON_AddNumberToObject(relaxed, sk_hand_dof(p->dof[a])->name,
                                    c->relaxed[p->dof[a]] * SK_RAD_TO_DEG);
        cJSON_AddStringToObject(o, "angles", "displacement");
        cJSON_AddStringToObject(o, "b_unit", "deg");
        cJSON *stiff = cJSON_AddObjectToObject(o, "stiffness");
        for (int i = 0; stiff && i < SK_HAND_DOF_COUNT; i++)
            if (c->constraints.has_stiffness[i] &&
                c->constraints.stiffness[i] != skel.dof[i].stiffness)
                cJSON_AddNumberToObject(stiff, sk_hand_dof(i)->name, c->constraints.stiffness[i]);
        cJSON *rows = cJSON_AddArrayToObject(o, "rows");
        for (int k = 0; rows && k < c->constraints.row_count; k++)
            cJSON_AddItemToArray(rows, row_json(&c->constraints.rows[k]));
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    size_t len = strlen(text);
    char *with_newline = malloc(len + 2);
    if (!with_newline) {
        cJSON_free(text);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    memcpy(with_newline, text, len);
    memcpy(with_newline + len, "\n", 2);
    cJSON_free(text);
    r = sk__hand_write_text_file(path, with_newline, err);
    free(with_newline);
    return r;
}

/* ----------------------------------------------------------------- read */

static sk_result read_dofs(const cJSON *root, sk_hand_potential *out, sk_error *err)
{
    const cJSON *dofs = cJSON_GetObjectItemCaseSensitive(root, "dofs");
    if (!dofs) return sk_fail(err, SK_ERROR_PARSE, "dofs: missing");
    if (!cJSON_IsArray(dofs))
        return sk_fail(err, SK_ERROR_PARSE, "dofs: expected an array of DOF names");
    bool seen[SK_HAND_DOF_COUNT] = {false};
    int i = 0;
    for (const cJSON *item = dofs->child; item; item = item->next, i++) {
        char path[32];
        snprintf(path, sizeof path, "dofs[%d]", i);
        if (!cJSON_IsString(item))
            return sk_fail(err, SK_ERROR_PARSE, "%s: expected a DOF name", path);
        int d;
        sk_result r = sk__hand_dof_by_name(item->valuestring, path, &d, err);
        if (r != SK_OK) return r;
        if (d < SK_HAND_WRIST_DOF_COUNT)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s: %s is a wrist DOF; a potential calibrates joints", path,
                           item->valuestring);
        if (seen[d])
            return sk_fail(err, SK_ERROR_PARSE, "%s: %s appears twice", path, item->valuestring);
        seen[d] = true;
    }
    out->dof_count = sk__hand_calibrated_dofs(seen, out->dof);
    if (out->dof_count == 0) return sk_fail(err, SK_ERROR_PARSE, "dofs: empty");
    return SK_OK;
}

static sk_result read_component(const cJSON *item, const char *path, const sk_hand_skeleton *skel,
                                const sk_hand_potential *p, sk_hand_potential_component *c,
                                sk_error *err)
{
    static const char *const extra[] = {"weight", "relaxed_deg", NULL};
    sk_result r = sk__hand_json_expect_object(item, path, err);
    if (r != SK_OK) return r;
    r = sk__hand_constraints_from_json(item, "", skel, extra, &c->constraints, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "%s", path);
    const char *angles = NULL;
    sk__hand_json_string(item, path, "angles", &angles, NULL);
    if (angles && strcmp(angles, "displacement") != 0)
        return sk_fail(err, SK_ERROR_PARSE, "%s.angles: a component's rows are on displacements",
                       path);
    c->weight = 0.0;
    r = sk__hand_json_number(item, path, "weight", 1e-12, 1.0, true, &c->weight, err);
    if (r != SK_OK) return r;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        c->relaxed[i] = skel->dof[i].relaxed;
        if (!c->constraints.has_stiffness[i]) {
            c->constraints.has_stiffness[i] = true;
            c->constraints.stiffness[i] = skel->dof[i].stiffness;
        }
        if (c->constraints.stiffness[i] > 1e9)
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s.stiffness.%s = %g is out of range (0, 1e9]", path,
                           sk_hand_dof(i)->name, c->constraints.stiffness[i]);
    }
    for (int k = 0; k < c->constraints.row_count; k++) {
        const sk_hand_row *row = &c->constraints.rows[k];
        for (int t = 0; t < row->term_count; t++)
            if (fabs(row->coeff[t]) > 1e6)
                return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                               "%s.rows[%d].terms.%s is out of range [-1e6, 1e6]", path, k,
                               sk_hand_dof(row->dof[t])->name);
    }
    char rpath[96];
    snprintf(rpath, sizeof rpath, "%s.relaxed_deg", path);
    const cJSON *relaxed = cJSON_GetObjectItemCaseSensitive(item, "relaxed_deg");
    if (!relaxed) return sk_fail(err, SK_ERROR_PARSE, "%s: missing", rpath);
    r = sk__hand_json_expect_object(relaxed, rpath, err);
    bool given[SK_HAND_DOF_COUNT] = {false};
    for (const cJSON *t = relaxed->child; r == SK_OK && t; t = t->next) {
        if (sk_preset_is_doc_key(t->string)) continue;
        char tpath[160];
        snprintf(tpath, sizeof tpath, "%s.%s", rpath, t->string);
        int d;
        r = sk__hand_dof_by_name(t->string, tpath, &d, err);
        if (r != SK_OK) break;
        bool calibrated = false;
        for (int a = 0; a < p->dof_count; a++) calibrated |= p->dof[a] == d;
        if (!calibrated) return sk_fail(err, SK_ERROR_PARSE, "%s: not one of \"dofs\"", tpath);
        if (!cJSON_IsNumber(t)) return sk_fail(err, SK_ERROR_PARSE, "%s: expected a number", tpath);
        double lo = skel->dof[d].min * SK_RAD_TO_DEG, hi = skel->dof[d].max * SK_RAD_TO_DEG,
               v = t->valuedouble;
        if (!(v >= lo - 1e-9 && v <= hi + 1e-9))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "%s = %g is outside the joint limits [%g, %g]", tpath, v, lo, hi);
        c->relaxed[d] = sk_clampd(v * SK_DEG_TO_RAD, skel->dof[d].min, skel->dof[d].max);
        given[d] = true;
    }
    if (r != SK_OK) return r;
    for (int a = 0; a < p->dof_count; a++)
        if (!given[p->dof[a]])
            return sk_fail(err, SK_ERROR_PARSE, "%s.%s: missing", rpath,
                           sk_hand_dof(p->dof[a])->name);
    r = sk__hand_check_positive_definite(skel, &c->constraints, err);
    if (r != SK_OK) return sk_error_prefix(err, r, "%s", path);
    return SK_OK;
}

static sk_result read_root(const cJSON *root, const sk_hand_skeleton *skel, sk_hand_potential *out,
                           sk_error *err)
{
    static const char *const keys[] = {"reading",        "dofs",       "scale", "samples",
                                       "prior_strength", "components", NULL};
    sk_result r = sk__hand_json_expect_object(root, "", err);
    if (r == SK_OK) r = sk__hand_json_check_keys(root, "", keys, err);
    if (r == SK_OK) r = read_dofs(root, out, err);
    double samples = 0.0;
    if (r == SK_OK)
        r = sk__hand_json_number(root, "", "scale", 1e-12, 1e12, true, &out->scale, err);
    if (r == SK_OK) r = sk__hand_json_number(root, "", "samples", 0, 1e8, false, &samples, err);
    if (r == SK_OK)
        r = sk__hand_json_number(root, "", "prior_strength", 0, 1e7, false, &out->prior_strength,
                                 err);
    if (r != SK_OK) return r;
    out->sample_count = (int)samples;
    const cJSON *comps = cJSON_GetObjectItemCaseSensitive(root, "components");
    if (!comps) return sk_fail(err, SK_ERROR_PARSE, "components: missing");
    if (!cJSON_IsArray(comps)) return sk_fail(err, SK_ERROR_PARSE, "components: expected an array");
    int m = cJSON_GetArraySize(comps);
    if (m < 1 || m > SK_HAND_POTENTIAL_MAX_COMPONENTS)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "components: %d entries, expected 1 to %d",
                       m, SK_HAND_POTENTIAL_MAX_COMPONENTS);
    out->component = calloc((size_t)m, sizeof *out->component);
    if (!out->component) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    out->component_count = m;
    int i = 0;
    double total = 0.0;
    for (const cJSON *item = comps->child; item; item = item->next, i++) {
        char path[48];
        snprintf(path, sizeof path, "components[%d]", i);
        r = read_component(item, path, skel, out, &out->component[i], err);
        if (r != SK_OK) return r;
        total += out->component[i].weight;
    }
    if (fabs(total - 1.0) > 1e-6)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "components: the weights sum to %g, not 1",
                       total);
    for (i = 0; i < m; i++) out->component[i].weight /= total;
    return SK_OK;
}

sk_result sk_hand_potential_parse(const char *text, size_t length, const char *source_name,
                                  const sk_hand_skeleton *skel, sk_hand_potential *out,
                                  sk_error *err)
{
    memset(out, 0, sizeof *out);
    cJSON *root = NULL;
    sk_result r = sk__hand_json_parse_strict(text, length, &root, err);
    if (r == SK_OK) {
        r = read_root(root, skel, out, err);
        cJSON_Delete(root);
    }
    if (r != SK_OK) {
        sk_hand_potential_free(out);
        sk_error_prefix(err, r, "%s", source_name);
    }
    return r;
}

sk_result sk_hand_potential_load_file(const char *path, const sk_hand_skeleton *skel,
                                      sk_hand_potential *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    memset(out, 0, sizeof *out);
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_hand_potential_parse(text, size, path, skel, out, err);
    free(text);
    return r;
}
