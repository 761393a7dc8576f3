/* Calibrated fits written as JSON (the rows of sk_hand_calibrate). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "formats/hand/hand_json_internal.h"

sk_result sk_hand_fits_write_json(const sk_hand_fit *fits, int count, sk_hand_weight_rule rule,
                                  const char *source_note, const char *path, sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    if (!root) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    bool thesis = rule != SK_HAND_WEIGHT_INVERSE_VARIANCE;
    cJSON_AddStringToObject(
        root, "description",
        "Constraint rows fitted to measured joint-angle samples (thesis 3.2.2)");
    if (source_note) cJSON_AddStringToObject(root, "source", source_note);
    cJSON_AddStringToObject(
        root, "reading",
        thesis ? "pair \"X:Y\" reads Y = A X + b, least squares on absolute angles "
                 "in degrees; W = mean squared distance from the line divided by "
                 "the largest over the pairs (eq. 3.18)"
               : "pair \"X:Y\" reads Y = A X + b, least squares on absolute angles "
                 "in degrees; W = smallest mean squared distance over the pairs "
                 "divided by this pair's (inverse variance)");
    cJSON_AddStringToObject(root, "angles", "absolute");
    cJSON_AddStringToObject(root, "b_unit", "deg");
    cJSON *rows = cJSON_AddArrayToObject(root, "rows");
    for (int k = 0; k < count && rows; k++) {
        const sk_hand_fit *f = &fits[k];
        cJSON *row = cJSON_CreateObject();
        if (!row) break;
        char pair[96], notes[128];
        snprintf(pair, sizeof pair, "%s:%s", sk_hand_dof(f->dof_x)->name,
                 sk_hand_dof(f->dof_y)->name);
        snprintf(notes, sizeof notes, "%d samples, rms distance from the line %.4g deg", f->count,
                 sqrt(f->mean_sq_distance) * SK_RAD_TO_DEG);
        cJSON_AddStringToObject(row, "pair", pair);
        cJSON_AddNumberToObject(row, "A", f->slope);
        cJSON_AddNumberToObject(row, "b", f->intercept * SK_RAD_TO_DEG);
        cJSON_AddNumberToObject(row, "W", f->weight);
        cJSON_AddStringToObject(row, "notes", notes);
        cJSON_AddItemToArray(rows, row);
    }
    char *text = cJSON_Print(root);
    cJSON_Delete(root);
    if (!text) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    size_t len = strlen(text);
    char *with_newline = malloc(len + 2);
    sk_result r;
    if (!with_newline) {
        r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    } else {
        memcpy(with_newline, text, len);
        with_newline[len] = '\n';
        with_newline[len + 1] = '\0';
        r = sk__hand_write_text_file(path, with_newline, err);
        free(with_newline);
    }
    cJSON_free(text);
    return r;
}
