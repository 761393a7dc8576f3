/* One frame of the showcase, stage by stage (the benchmark's split): melody -> intents
 * and wrist, posture solve with contact, the forearm's tissue step, the meshes (hand
 * skinning, forearm normals), render scene, ray tracing. */
#include <math.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

sk_result sk_showcase_render_frame(sk_showcase *sc, int frame, sk_image *image,
                                   sk_showcase_stats *stats, sk_error *err)
{
    memset(image, 0, sizeof *image);
    if (frame < 0 || frame >= sc->frame_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "frame %d is out of range [0, %d]", frame,
                       sc->frame_count - 1);
    double t = frame / sc->desc.fps;
    double t0 = sk_time_seconds();
    sk__intent in;
    sk__performance_at(&sc->perf, t, &in);
    double t1 = sk_time_seconds();
    sk_showcase_pose pose;
    sk_result r = sk__contact_solve(&sc->contact, &in, t, &pose, err);
    double t2 = sk_time_seconds();
    if (r == SK_OK) r = sk__forearm_advance(sc, t, err);
    double t2b = sk_time_seconds();
    sk_mesh hand = {0};
    if (r == SK_OK) r = sk__hand_mesh_posed(sc, &pose.frames, &hand, err);
    if (r == SK_OK) r = sk__forearm_render_mesh(sc, t, err);
    double t3 = sk_time_seconds();
    if (r == SK_OK) r = sk__scene_build(sc, &pose, &hand, sc->scene, err);
    sk_render_scene *scene = NULL;
    if (r == SK_OK) r = sk_render_scene_create(sc->scene, &scene, err);
    sk_mesh_free(&hand);
    double t4 = sk_time_seconds();
    if (r == SK_OK) r = sk_render_scene_render(scene, NULL, image, NULL, err);
    double t5 = sk_time_seconds();
    sk_render_scene_destroy(scene);
    if (stats) {
        stats->frames++;
        stats->seconds_input += t1 - t0;
        stats->seconds_solve += t2 - t1;
        stats->seconds_tissue += t2b - t2;
        stats->seconds_skin += t3 - t2b;
        stats->seconds_scene += t4 - t3;
        stats->seconds_render += t5 - t4;
    }
    return r;
}
