/* The 21 hand landmarks of the common hand-pose datasets' order (wrist; then per finger
 * from thumb to little, base to tip: thumb CMC, MCP, IP, tip; index..little MCP, PIP,
 * DIP, tip) from the skeleton's joint centres, per frame, as CSV or JSON. The tips are
 * the ends of the distal links, where the surface's fingertips are. */
#include <stdio.h>
#include <stdlib.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

static const char *const names[SK_HAND_LANDMARK_COUNT] = {
    "wrist",     "thumb_cmc", "thumb_mcp",  "thumb_ip",   "thumb_tip",  "index_mcp",  "index_pip",
    "index_dip", "index_tip", "middle_mcp", "middle_pip", "middle_dip", "middle_tip", "ring_mcp",
    "ring_pip",  "ring_dip",  "ring_tip",   "little_mcp", "little_pip", "little_dip", "little_tip"};

const char *sk_hand_landmark_name(int i)
{
    return i >= 0 && i < SK_HAND_LANDMARK_COUNT ? names[i] : NULL;
}

int sk_hand_landmark_point(int i)
{
    if (i < 0 || i >= SK_HAND_LANDMARK_COUNT) return -1;
    if (i == 0) return 0;
    if (i <= 4) return i; /* T.CMC T.MCP T.IP T.tip are points 1..4 */
    int finger = (i - 5) / 4, k = (i - 5) % 4;
    return 5 + 5 * finger + 1 + k; /* skip each finger's CMC */
}

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
            ok &= fprintf(fp, "%s\"%s\"", i ? ", " : "", names[i]) > 0;
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
                ok &= fprintf(fp, "%d,%d,%s,%.6g,%.6g,%.6g\n", f, i, names[i], p.x, p.y, p.z) > 0;
        }
        if (json) ok &= fprintf(fp, "]%s\n", f + 1 < frame_count ? "," : "") > 0;
    }
    if (json) ok &= fprintf(fp, " ]}\n") > 0;
    if (!ok) return sk_atomic_file_write_failed(&file, err);
    return sk_atomic_file_commit(&file, err);
}
