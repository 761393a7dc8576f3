/* The landmark track as CSV or JSON: one row a frame, the 21 named landmarks' positions
 * (the format is described at sk_hand_landmarks_write in include/shitsukan/hand_surface.h). */
#include <stdio.h>
#include <stdlib.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "shitsukan/io.h"

sk_result sk_hand_landmarks_write(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                                  sk_hand_positions_format format, const char *path, sk_error *err)
{
    if (frame_count < 1)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame_count = %d must be at least 1",
                       frame_count);
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    FILE *fp = file.fp;
    bool json = format == SK_HAND_POSITIONS_JSON;
    int ok = 1;
    if (json) {
        ok &= fprintf(fp, "{\"units\": \"mm\", \"side\": \"%s\", \"landmarks\": [",
                      s->side == SK_HAND_SIDE_LEFT ? "left" : "right") > 0;
        for (int i = 0; i < SK_HAND_LANDMARK_COUNT; i++)
            ok &= fprintf(fp, "%s\"%s\"", i ? ", " : "", sk_hand_landmark_name(i)) > 0;
        ok &= fprintf(fp, "],\n \"frames\": [\n") > 0;
    } else {
        ok &= fprintf(fp, "frame,landmark,name,x_mm,y_mm,z_mm\n") > 0;
    }
    for (int f = 0; f < frame_count && ok; f++) {
        sk_hand_frames fr;
        sk_hand_forward(s, dofs + (size_t)f * SK_HAND_DOF_COUNT, &fr);
        if (json) ok &= fprintf(fp, "  [") > 0;
        for (int i = 0; i < SK_HAND_LANDMARK_COUNT; i++) {
            sk_vec3d p = fr.point[sk_hand_landmark_point(i)];
            if (json)
                ok &= fprintf(fp, "%s[%.6g, %.6g, %.6g]", i ? ", " : "", p.x, p.y, p.z) > 0;
            else
                ok &= fprintf(fp, "%d,%d,%s,%.6g,%.6g,%.6g\n", f, i, sk_hand_landmark_name(i), p.x,
                              p.y, p.z) > 0;
        }
        if (json) ok &= fprintf(fp, "]%s\n", f + 1 < frame_count ? "," : "") > 0;
    }
    if (json) ok &= fprintf(fp, " ]}\n") > 0;
    if (!ok) return sk_atomic_file_write_failed(&file, err);
    return sk_atomic_file_commit(&file, err);
}
