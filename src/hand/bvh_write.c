/* BVH export of hand motion: the link tree as a BVH hierarchy whose rest pose is the
 * skeleton with every DOF at zero (OFFSETs in mm), the root with 6 channels and every
 * joint with 3 rotation channels in the model's 3-2-1 order (Zrotation Yrotation
 * Xrotation, eq. 3.4). BVH rest frames are aligned with the world, so each channel
 * triple is the joint's rotation relative to its rest orientation. */
#include <stdio.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

static void indent(FILE *out, int depth)
{
    for (int i = 0; i < depth; i++) fputc('\t', out);
}

static void write_vec(FILE *out, sk_vec3d v)
{
    fprintf(out, "%.9f %.9f %.9f", v.x, v.y, v.z);
}

static void write_chain(FILE *out, const sk_hand_skeleton *s, const sk_hand_frames *ref, int link,
                        int depth)
{
    int parent = s->parent[link];
    sk_vec3d offset = sk_v3d_sub(ref->point[sk_hand_link_point(link)], ref->point[sk_hand_link_point(parent)]);
    indent(out, depth);
    fprintf(out, "JOINT %s\n", sk_hand_link_name(link));
    indent(out, depth);
    fputs("{\n", out);
    indent(out, depth + 1);
    fputs("OFFSET ", out);
    write_vec(out, offset);
    fputc('\n', out);
    indent(out, depth + 1);
    fputs("CHANNELS 3 Zrotation Yrotation Xrotation\n", out);
    bool last = link == SK_HAND_LINK_COUNT - 1 || s->parent[link + 1] != link;
    if (last) {
        int tip = sk_hand_link_end_point(link);
        indent(out, depth + 1);
        fputs("End Site\n", out);
        indent(out, depth + 1);
        fputs("{\n", out);
        indent(out, depth + 2);
        fputs("OFFSET ", out);
        write_vec(out, sk_v3d_sub(ref->point[tip], ref->point[sk_hand_link_point(link)]));
        fputc('\n', out);
        indent(out, depth + 1);
        fputs("}\n", out);
    } else {
        write_chain(out, s, ref, link + 1, depth + 1);
    }
    indent(out, depth);
    fputs("}\n", out);
}

static void write_angles(FILE *out, sk_mat3d local)
{
    double x, y, z;
    sk_hand_euler321_from_matrix(local, &x, &y, &z);
    fprintf(out, " %.9f %.9f %.9f", z * SK_RAD_TO_DEG, y * SK_RAD_TO_DEG, x * SK_RAD_TO_DEG);
}

sk_result sk_hand_bvh_write_stream(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                                   double frame_time, FILE *out)
{
    double zero[SK_HAND_DOF_COUNT] = {0};
    sk_hand_frames ref, cur;
    sk_hand_forward(s, zero, &ref);
    fputs("HIERARCHY\nROOT Hand\n{\n\tOFFSET 0.000000000 0.000000000 0.000000000\n"
          "\tCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation Xrotation\n",
          out);
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) write_chain(out, s, &ref, sk_hand__first_link(f), 1);
    fputs("}\nMOTION\n", out);
    fprintf(out, "Frames: %d\nFrame Time: %.9f\n", frame_count, frame_time);
    for (int fr = 0; fr < frame_count; fr++) {
        const double *q = dofs + (size_t)fr * SK_HAND_DOF_COUNT;
        sk_hand_forward(s, q, &cur);
        /* global rotation relative to rest: G = R R_ref^T; local = G_parent^T G */
        sk_mat3d g[SK_HAND_LINK_COUNT];
        for (int l = 0; l < SK_HAND_LINK_COUNT; l++)
            g[l] = sk_m3d_mul(cur.rotation[l], sk_m3d_transpose(ref.rotation[l]));
        write_vec(out, cur.point[0]);
        write_angles(out, g[0]);
        for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
            int first = sk_hand__first_link(f), n = sk_hand__link_count_of_finger(f);
            for (int l = first; l < first + n; l++)
                write_angles(out, sk_m3d_mul(sk_m3d_transpose(g[s->parent[l]]), g[l]));
        }
        fputc('\n', out);
    }
    return ferror(out) ? SK_ERROR_IO : SK_OK;
}

sk_result sk_hand_bvh_write(const sk_hand_skeleton *s, const double *dofs, int frame_count,
                            double frame_time, const char *path, sk_error *err)
{
    if (frame_count < 1) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "no frames to write");
    if (!(frame_time > 0.0)) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame time %g must be positive", frame_time);
    sk_atomic_file file;
    sk_result r = sk_atomic_file_open(&file, path, err);
    if (r != SK_OK) return r;
    if (sk_hand_bvh_write_stream(s, dofs, frame_count, frame_time, file.fp) != SK_OK) {
        return sk_atomic_file_write_failed(&file, err);
    }
    return sk_atomic_file_commit(&file, err);
}
