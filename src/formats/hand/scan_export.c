/* Files of the scan pipeline (thesis 4.1): Table 4.1 beside the thesis's own figures
 * (JSON and text), the registration with its per-marker residuals, the control points of
 * the 96 Bezier patches (JSON), and the patches tessellated into one mesh. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "models/hand_scan/scan_internal.h"
#include "shitsukan/io.h"
#include "formats/hand/hand_json_internal.h"

static const char *const side_names[SK_HAND_SCAN_SIDE_COUNT] = {"palm", "back"};

static sk_result write_json(cJSON *root, const char *path, sk_error *err)
{
    if (!root) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: building JSON", path);
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s: printing JSON", path);
    size_t n = strlen(text);
    char *with_newline = malloc(n + 2);
    if (!with_newline) {
        free(text);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "%s", path);
    }
    memcpy(with_newline, text, n);
    with_newline[n] = '\n';
    with_newline[n + 1] = '\0';
    free(text);
    sk_result r = sk__hand_write_text_file(path, with_newline, err);
    free(with_newline);
    return r;
}

/* Rounded to 6 significant digits, so files do not carry noise digits. */
static cJSON *number(double v)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%.6g", v);
    return cJSON_CreateNumber(strtod(buf, NULL));
}

static cJSON *vec3(sk_vec3d p)
{
    cJSON *a = cJSON_CreateArray();
    cJSON_AddItemToArray(a, number(p.x));
    cJSON_AddItemToArray(a, number(p.y));
    cJSON_AddItemToArray(a, number(p.z));
    return a;
}

static cJSON *error_entry(const sk_hand_fit_error *e)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "mean_mm", number(e->mean_mm));
    cJSON_AddItemToObject(o, "max_mm", number(e->max_mm));
    cJSON_AddNumberToObject(o, "points", (double)e->points);
    cJSON_AddNumberToObject(o, "worst_patch", e->worst_patch);
    return o;
}

static cJSON *thesis_entry(double mean, double max)
{
    cJSON *o = cJSON_CreateObject();
    cJSON_AddItemToObject(o, "mean_mm", number(mean));
    if (max > 0) cJSON_AddItemToObject(o, "max_mm", number(max));
    return o;
}

sk_result sk_hand_table41_write_json(const sk_hand_table41 *t, const char *path, sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(
        root, "description",
        "Fitting error of the 96 bicubic Bezier patches in the form of Table 4.1 of Yasumuro's "
        "thesis (2000, sec. 4.1.4): mean and largest distance of the fitted points to the nearest "
        "facet of a 100 x 100 split of their patch, palm and back, in mm");
    cJSON *thesis = cJSON_AddObjectToObject(root, "thesis");
    cJSON_AddItemToObject(thesis, "palm",
                          thesis_entry(SK_HAND_THESIS_PALM_MEAN_MM, SK_HAND_THESIS_PALM_MAX_MM));
    cJSON_AddItemToObject(thesis, "back",
                          thesis_entry(SK_HAND_THESIS_BACK_MEAN_MM, SK_HAND_THESIS_BACK_MAX_MM));
    cJSON_AddItemToObject(thesis, "all", thesis_entry(SK_HAND_THESIS_ALL_MEAN_MM, 0));
    cJSON *scan = cJSON_AddObjectToObject(root, "scan");
    cJSON_AddStringToObject(scan, "points",
                            "the scanned, registered points the patches were fitted to");
    for (int s = 0; s < SK_HAND_SCAN_SIDE_COUNT; s++)
        cJSON_AddItemToObject(scan, side_names[s], error_entry(&t->scan[s]));
    cJSON_AddItemToObject(scan, "all", error_entry(&t->scan_all));
    if (t->has_truth) {
        cJSON *truth = cJSON_AddObjectToObject(root, "truth");
        cJSON_AddStringToObject(truth, "points",
                                "the true surface points those samples measured (before noise and "
                                "quantisation, with the exact registration)");
        for (int s = 0; s < SK_HAND_SCAN_SIDE_COUNT; s++)
            cJSON_AddItemToObject(truth, side_names[s], error_entry(&t->truth[s]));
        cJSON_AddItemToObject(truth, "all", error_entry(&t->truth_all));
    } else {
        cJSON_AddNullToObject(root, "truth");
    }
    cJSON *fitted = cJSON_AddObjectToObject(root, "patches_fitted");
    for (int s = 0; s < SK_HAND_SCAN_SIDE_COUNT; s++)
        cJSON_AddNumberToObject(fitted, side_names[s], t->patches_fitted[s]);
    return write_json(root, path, err);
}

sk_result sk_hand_table41_write_text(const sk_hand_table41 *t, const char *path, sk_error *err)
{
    char text[4096];
    size_t n = 0;
#define OUT(...) n += (size_t)snprintf(text + n, sizeof text - n, __VA_ARGS__)
    OUT("Table 4.1  Fitting error of the Bezier patches [mm]: distance of each fitted point to "
        "the\n"
        "nearest facet of its patch split 100 x 100 (Yasumuro 2000, sec. 4.1.4, beside this "
        "run)\n\n");
    OUT("%-6s %12s %12s   %12s %12s   %12s %12s   %8s\n", "side", "thesis mean", "thesis max",
        "scan mean", "scan max", "truth mean", "truth max", "points");
    static const double thesis[3][2] = {{SK_HAND_THESIS_PALM_MEAN_MM, SK_HAND_THESIS_PALM_MAX_MM},
                                        {SK_HAND_THESIS_BACK_MEAN_MM, SK_HAND_THESIS_BACK_MAX_MM},
                                        {SK_HAND_THESIS_ALL_MEAN_MM, 0}};
    for (int row = 0; row < 3; row++) {
        const sk_hand_fit_error *s = row < 2 ? &t->scan[row] : &t->scan_all;
        const sk_hand_fit_error *tr = row < 2 ? &t->truth[row] : &t->truth_all;
        char tmax[16] = "-", truth_mean[16] = "-", truth_max[16] = "-";
        if (thesis[row][1] > 0) snprintf(tmax, sizeof tmax, "%.2g", thesis[row][1]);
        if (t->has_truth) {
            snprintf(truth_mean, sizeof truth_mean, "%.3g", tr->mean_mm);
            snprintf(truth_max, sizeof truth_max, "%.3g", tr->max_mm);
        }
        OUT("%-6s %12.2g %12s   %12.3g %12.3g   %12s %12s   %8zu\n",
            row == 0   ? "palm"
            : row == 1 ? "back"
                       : "all",
            thesis[row][0], tmax, s->mean_mm, s->max_mm, truth_mean, truth_max, s->points);
    }
    OUT("\npatches fitted: %d palm, %d back (of 48 each)\n", t->patches_fitted[0],
        t->patches_fitted[1]);
    if (t->scan_all.worst_patch >= 0) OUT("largest error: patch %d\n", t->scan_all.worst_patch);
    if (!t->has_truth) OUT("truth: not known for a point cloud given as input\n");
#undef OUT
    return sk__hand_write_text_file(path, text, err);
}

static cJSON *rigid_json(const sk_hand_rigid *t)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *rot = cJSON_AddArrayToObject(o, "rotation");
    for (int r = 0; r < 3; r++)
        cJSON_AddItemToArray(
            rot, vec3(sk_v3d(t->rotation.m[r][0], t->rotation.m[r][1], t->rotation.m[r][2])));
    cJSON_AddItemToObject(o, "translation_mm", vec3(t->translation));
    return o;
}

sk_result sk_hand_registration_write_json(const sk_hand_registration *reg,
                                          const sk_hand_markers *markers, const char *path,
                                          sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(
        root, "description",
        "Registration of the back scan onto the palm scan by least squares on the 9 markers "
        "(Yasumuro 2000, sec. 4.1.1): a rigid transform back-scanner frame -> palm-scanner frame, "
        "x' = R x + t (rows of R), and each marker's residual after it");
    cJSON *list = cJSON_AddArrayToObject(root, "markers");
    for (int k = 0; k < markers->count; k++) {
        cJSON *m = cJSON_CreateObject();
        cJSON_AddStringToObject(m, "name", markers->name[k]);
        cJSON_AddItemToObject(m, "palm_scan_mm", vec3(reg->palm_centre[k]));
        cJSON_AddItemToObject(m, "back_scan_mm", vec3(reg->back_centre[k]));
        cJSON_AddNumberToObject(m, "palm_samples", reg->palm_used[k]);
        cJSON_AddNumberToObject(m, "back_samples", reg->back_used[k]);
        cJSON_AddItemToObject(m, "residual_mm", number(reg->residual_mm[k]));
        cJSON_AddItemToArray(list, m);
    }
    cJSON_AddItemToObject(root, "rms_mm", number(reg->rms_mm));
    cJSON_AddItemToObject(root, "estimated", rigid_json(&reg->back_to_palm));
    if (reg->has_truth) {
        cJSON_AddItemToObject(root, "truth", rigid_json(&reg->truth));
        cJSON_AddItemToObject(root, "rotation_error_deg", number(reg->rotation_error_deg));
        cJSON_AddItemToObject(root, "translation_error_mm", number(reg->translation_error_mm));
    }
    return write_json(root, path, err);
}

sk_result sk_hand_patches_write_json(const sk_hand_patch_set *set, const char *path, sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    cJSON_AddStringToObject(
        root, "description",
        "Bicubic Bezier patches fitted to the scan (Yasumuro 2000, sec. 4.1.4): Q(u, v) = sum "
        "B_i(u) B_j(v) P_ij with the cubic Bernstein basis; control_points_mm lists P_00, P_01, "
        ".., "
        "P_03, P_10, .., P_33 (i along u, about the link; j along v, along the link), hand frame");
    cJSON_AddStringToObject(root, "unit", "mm");
    cJSON *list = cJSON_AddArrayToObject(root, "patches");
    for (int k = 0; k < set->count; k++) {
        const sk_hand_patch *p = &set->patch[k];
        cJSON *o = cJSON_CreateObject();
        cJSON_AddNumberToObject(o, "index", k);
        cJSON_AddStringToObject(o, "side", side_names[p->side == SK_HAND_SCAN_BACK]);
        cJSON_AddStringToObject(o, "link", sk_hand_link_name(p->link));
        cJSON_AddNumberToObject(o, "along", p->along);
        cJSON_AddNumberToObject(o, "around", p->around);
        cJSON_AddBoolToObject(o, "fitted", set->fitted[k]);
        cJSON_AddNumberToObject(o, "points", (double)set->data[k].count);
        if (set->fitted[k]) {
            cJSON *cp = cJSON_AddArrayToObject(o, "control_points_mm");
            for (int i = 0; i < 4; i++)
                for (int j = 0; j < 4; j++) cJSON_AddItemToArray(cp, vec3(p->p[i][j]));
            cJSON_AddNumberToObject(o, "corrections", set->fit[k].iterations);
            cJSON_AddItemToObject(o, "rms_mm", number(set->fit[k].rms_final_mm));
            double mean = 0, max = 0;
            if (set->error_scan[k]) {
                for (size_t i = 0; i < set->data[k].count; i++) {
                    mean += set->error_scan[k][i];
                    if (set->error_scan[k][i] > max) max = set->error_scan[k][i];
                }
                mean /= (double)set->data[k].count;
                cJSON_AddItemToObject(o, "mean_error_mm", number(mean));
                cJSON_AddItemToObject(o, "max_error_mm", number(max));
            }
        }
        cJSON_AddItemToArray(list, o);
    }
    return write_json(root, path, err);
}

sk_result sk_hand_patches_tessellate(const sk_hand_patch *patches, int count, int n, sk_mesh *out,
                                     sk_error *err)
{
    memset(out, 0, sizeof *out);
    if (n == 0) n = 16;
    sk_result r = sk_check_range_i(err, "tessellation", n, 1, 256);
    if (r == SK_OK) r = sk_check_range_i(err, "patch count", count, 1, 1 << 20);
    if (r != SK_OK) return r;
    size_t per_v = (size_t)(n + 1) * (size_t)(n + 1), per_t = 2 * (size_t)n * (size_t)n;
    r = sk_mesh_create(out, per_v * (size_t)count, per_t * (size_t)count,
                       SK_MESH_NORMALS | SK_MESH_UVS, err);
    float *attr = NULL;
    if (r == SK_OK) r = sk_mesh_add_attribute(out, "patch", 1, &attr, err);
    if (r != SK_OK) {
        sk_mesh_free(out);
        return r;
    }
    for (int k = 0; k < count; k++) {
        size_t v0 = per_v * (size_t)k;
        for (int a = 0; a <= n; a++)
            for (int b = 0; b <= n; b++) {
                size_t v = v0 + (size_t)a * (size_t)(n + 1) + (size_t)b;
                double u = (double)a / n, w = (double)b / n;
                sk_vec3d du, dw;
                sk_vec3d p = sk_hand_patch_eval(&patches[k], u, w, &du, &dw);
                sk_vec3d nn = sk_v3d_normalize(sk_v3d_cross(du, dw));
                out->positions[3 * v] = (float)p.x, out->positions[3 * v + 1] = (float)p.y,
                                   out->positions[3 * v + 2] = (float)p.z;
                out->normals[3 * v] = (float)nn.x, out->normals[3 * v + 1] = (float)nn.y,
                                 out->normals[3 * v + 2] = (float)nn.z;
                if (sk_v3d_length(nn) == 0) out->normals[3 * v + 2] = 1.0f;
                out->uvs[2 * v] = (float)u, out->uvs[2 * v + 1] = (float)w;
                attr[v] = (float)k;
            }
        size_t t0 = per_t * (size_t)k;
        for (int a = 0; a < n; a++)
            for (int b = 0; b < n; b++) {
                uint32_t i00 = (uint32_t)(v0 + (size_t)a * (size_t)(n + 1) + (size_t)b),
                         i10 = i00 + (uint32_t)(n + 1);
                uint32_t *ix = out->indices + 3 * (t0 + 2 * ((size_t)a * (size_t)n + (size_t)b));
                ix[0] = i00, ix[1] = i10, ix[2] = i10 + 1;
                ix[3] = i00, ix[4] = i10 + 1, ix[5] = i00 + 1;
            }
    }
    return SK_OK;
}

sk_result sk_hand_cloud_write_ply(const sk_hand_cloud *cloud, const char *path, sk_error *err)
{
    sk_mesh m;
    sk_result r = sk_mesh_create(&m, cloud->count, 0, 0, err);
    float *side = NULL, *truth = NULL;
    if (r == SK_OK) r = sk_mesh_add_attribute(&m, "side", 1, &side, err);
    if (r == SK_OK && cloud->true_position) r = sk_mesh_add_attribute(&m, "truth", 3, &truth, err);
    if (r == SK_OK) {
        for (size_t i = 0; i < cloud->count; i++) {
            m.positions[3 * i] = (float)cloud->position[i].x;
            m.positions[3 * i + 1] = (float)cloud->position[i].y;
            m.positions[3 * i + 2] = (float)cloud->position[i].z;
            side[i] = cloud->side[i];
            if (truth) {
                truth[3 * i] = (float)cloud->true_position[i].x;
                truth[3 * i + 1] = (float)cloud->true_position[i].y;
                truth[3 * i + 2] = (float)cloud->true_position[i].z;
            }
        }
        r = sk_mesh_write_ply(&m, path, err);
    }
    sk_mesh_free(&m);
    return r;
}
