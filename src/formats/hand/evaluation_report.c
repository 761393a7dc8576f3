/* The report of a held-out evaluation (thesis 3.2's model against the mean, linear
 * regression and a PCA prior): a JSON list, one entry per pin set, and a text table. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "formats/hand/hand_json_internal.h"

/* Degrees rounded to 1e-6 (the JSON stays readable; far below any measurement). */
static double deg(double rad) { return round(rad * SK_RAD_TO_DEG * 1e6) / 1e6; }

sk_result sk_hand_evaluation_write_json(const sk_hand_evaluation *eval, const char *path,
                                        sk_error *err)
{
    cJSON *root = cJSON_CreateArray();
    if (!root) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    for (int p = 0; p < eval->pin_set_count; p++) {
        const sk_hand_pin_result *res = &eval->result[p];
        cJSON *o = cJSON_CreateObject();
        if (!o) break;
        cJSON_AddItemToArray(root, o);
        cJSON *pins = cJSON_AddArrayToObject(o, "pins");
        for (int k = 0; pins && k < res->pins.count; k++)
            cJSON_AddItemToArray(pins, cJSON_CreateString(sk_hand_dof(res->pins.dof[k])->name));
        cJSON_AddNumberToObject(o, "model_rms_deg", deg(res->model_all));
        cJSON *per = cJSON_AddObjectToObject(o, "per_joint");
        for (int j = 0; per && j < res->joint_count; j++)
            cJSON_AddNumberToObject(per, sk_hand_dof(res->joint[j])->name, deg(res->model[j]));
        cJSON *base = cJSON_AddObjectToObject(o, "baselines");
        if (!base) break;
        cJSON_AddNumberToObject(base, "mean", deg(res->mean_all));
        cJSON_AddNumberToObject(base, "linear", deg(res->linear_all));
        cJSON *pca = cJSON_AddObjectToObject(base, "pca");
        if (!pca) break;
        cJSON_AddNumberToObject(pca, "k", eval->pca_k);
        cJSON_AddNumberToObject(pca, "rms_deg", deg(res->pca_all));
        cJSON *solves = cJSON_AddObjectToObject(o, "solves");
        if (!solves) break;
        cJSON_AddNumberToObject(solves, "count", res->solves);
        cJSON_AddNumberToObject(solves, "not_converged", res->unconverged);
        cJSON_AddNumberToObject(solves, "largest_residual", res->max_residual);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    size_t len = strlen(text);
    char *buf = malloc(len + 2);
    if (!buf) {
        cJSON_free(text);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    memcpy(buf, text, len);
    memcpy(buf + len, "\n", 2);
    cJSON_free(text);
    sk_result r = sk__hand_write_text_file(path, buf, err);
    free(buf);
    return r;
}

void sk_hand_evaluation_print(const sk_hand_evaluation *eval, const char *model_name, FILE *out)
{
    char pca[16];
    snprintf(pca, sizeof pca, "PCA %d", eval->pca_k);
    for (int p = 0; p < eval->pin_set_count; p++) {
        const sk_hand_pin_result *res = &eval->result[p];
        fprintf(out, "%spins ", p ? "\n" : "");
        for (int k = 0; k < res->pins.count; k++)
            fprintf(out, "%s%s", k ? "," : "", sk_hand_dof(res->pins.dof[k])->name);
        fprintf(out, ": held-out RMS error in degrees (%d samples, %d folds)\n", eval->sample_count,
                eval->fold_count);
        fprintf(out, "%-12s %10s %8s %8s %8s\n", "joint", model_name ? model_name : "model", "mean",
                "linear", pca);
        for (int j = 0; j < res->joint_count; j++)
            fprintf(out, "%-12s %10.2f %8.2f %8.2f %8.2f\n", sk_hand_dof(res->joint[j])->name,
                    res->model[j] * SK_RAD_TO_DEG, res->mean[j] * SK_RAD_TO_DEG,
                    res->linear[j] * SK_RAD_TO_DEG, res->pca[j] * SK_RAD_TO_DEG);
        fprintf(out, "%-12s %10.2f %8.2f %8.2f %8.2f\n", "all", res->model_all * SK_RAD_TO_DEG,
                res->mean_all * SK_RAD_TO_DEG, res->linear_all * SK_RAD_TO_DEG,
                res->pca_all * SK_RAD_TO_DEG);
        double vs = res->pca_all > 0 ? 100.0 * (res->model_all / res->pca_all - 1.0) : 0.0;
        fprintf(out,
                "model vs PCA %d: %+.1f %%; solves: %d, %d not converged (largest residual %.2g)\n",
                eval->pca_k, vs, res->solves, res->unconverged, res->max_residual);
    }
}
