/* Joint positions (eq. 3.6) of poses and animations as CSV or JSON, and a single pose
 * (DOF values and positions) as JSON, for other tools. */
#include <stdio.h>
#include <stdlib.h>

#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "formats/json_file.h"
#include "shitsukan/io.h"

static sk_result write_csv(FILE *out, const sk_hand_skeleton *s, const double *dofs, int frames)
{
    fputs("frame,point,x_mm,y_mm,z_mm\n", out);
    sk_hand_frames f;
    for (int fr = 0; fr < frames; fr++) {
        sk_hand_forward(s, dofs + (size_t)fr * SK_HAND_DOF_COUNT, &f);
        for (int p = 0; p < SK_HAND_POINT_COUNT; p++)
            fprintf(out, "%d,%s,%.6f,%.6f,%.6f\n", fr, sk_hand_point_name(p), f.point[p].x,
                    f.point[p].y, f.point[p].z);
    }
    return ferror(out) ? SK_ERROR_IO : SK_OK;
}

static sk_result write_json(FILE *out, const sk_hand_skeleton *s, const double *dofs, int frames)
{
    fprintf(out, "{\n  \"side\": \"%s\",\n  \"unit\": \"mm\",\n  \"points\": [",
            s->side == SK_HAND_SIDE_LEFT ? "left" : "right");
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++)
        fprintf(out, "%s\"%s\"", p ? ", " : "", sk_hand_point_name(p));
    fputs("],\n  \"frames\": [\n", out);
    sk_hand_frames f;
    for (int fr = 0; fr < frames; fr++) {
        sk_hand_forward(s, dofs + (size_t)fr * SK_HAND_DOF_COUNT, &f);
        fputs("    [", out);
        for (int p = 0; p < SK_HAND_POINT_COUNT; p++)
            fprintf(out, "%s[%.6f, %.6f, %.6f]", p ? ", " : "", f.point[p].x, f.point[p].y,
                    f.point[p].z);
        fprintf(out, "]%s\n", fr + 1 < frames ? "," : "");
    }
    fputs("  ]\n}\n", out);
    return ferror(out) ? SK_ERROR_IO : SK_OK;
}

sk_result sk_hand_positions_write(const sk_hand_skeleton *s, const double *dofs, int frames,
                                  sk_hand_positions_format format, const char *path, sk_error *err)
{
    if (frames < 1) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no frames to write");
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    r = format == SK_HAND_POSITIONS_JSON ? write_json(file.fp, s, dofs, frames)
                                         : write_csv(file.fp, s, dofs, frames);
    if (r != SK_OK) {
        return sk_atomic_file_write_failed(&file, err);
    }
    return sk_atomic_file_commit(&file, err);
}

sk_result sk_hand_angles_write_csv(const double *dofs, int frames, double frame_time,
                                   const char *path, sk_error *err)
{
    if (frames < 1) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no frames to write");
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    fputs("frame,time_s", file.fp);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) fprintf(file.fp, ",%s", sk_hand_dof(i)->name);
    fputc('\n', file.fp);
    for (int f = 0; f < frames; f++) {
        fprintf(file.fp, "%d,%.6f", f, f * frame_time);
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
            fprintf(file.fp, ",%.6f",
                    sk__hand_to_file_units(i, dofs[(size_t)f * SK_HAND_DOF_COUNT + i]));
        fputc('\n', file.fp);
    }
    if (ferror(file.fp)) {
        return sk_atomic_file_write_failed(&file, err);
    }
    return sk_atomic_file_commit(&file, err);
}

sk_result sk_hand_pose_write_json(const sk_hand_skeleton *s, const double dofs[SK_HAND_DOF_COUNT],
                                  const sk_hand_solve_info *info, const char *path, sk_error *err)
{
    cJSON *root = cJSON_CreateObject();
    cJSON *d = root ? cJSON_AddObjectToObject(root, "dofs") : NULL;
    cJSON *pts = root ? cJSON_AddObjectToObject(root, "points_mm") : NULL;
    if (!d || !pts) {
        cJSON_Delete(root);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    cJSON_AddStringToObject(root, "side", s->side == SK_HAND_SIDE_LEFT ? "left" : "right");
    cJSON_AddStringToObject(root, "units", "dofs in degrees (wrist.tx/ty/tz in mm), points in mm");
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        cJSON_AddNumberToObject(d, sk_hand_dof(i)->name, sk__hand_to_file_units(i, dofs[i]));
    sk_hand_frames f;
    sk_hand_forward(s, dofs, &f);
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
        double v[3] = {f.point[p].x, f.point[p].y, f.point[p].z};
        cJSON_AddItemToObject(pts, sk_hand_point_name(p), cJSON_CreateDoubleArray(v, 3));
    }
    if (info) {
        cJSON *si = cJSON_AddObjectToObject(root, "solve");
        if (si) {
            cJSON_AddNumberToObject(si, "residual", info->residual);
            cJSON_AddNumberToObject(si, "energy", info->energy);
            cJSON_AddNumberToObject(si, "clamped_at_limits", info->clamped_count);
            cJSON_AddNumberToObject(si, "pins_clamped", info->pins_clamped);
            cJSON_AddNumberToObject(si, "newton_iterations", info->newton_iterations);
            cJSON_AddBoolToObject(si, "converged", info->converged);
        }
    }
    return sk__json_write_file(root, path, err);
}
