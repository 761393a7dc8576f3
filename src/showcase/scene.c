/* A frame's render scene: the stage (cabinet, floor, lights), the 88 keys turned as the
 * pose says, the hand, and the camera framing the keys the melody plays. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "showcase/showcase_internal.h"

#define CAMERA_FOV_DEG 30.0

void sk__scene_frame_camera(const sk_showcase *sc, sk_render_camera_desc *camera)
{
    /* the span of the wrist's travel and of the keys, with room for the hand */
    double lo = INFINITY, hi = -INFINITY;
    for (int i = 0; i < sc->melody.note_count; i++) {
        double x = sk_piano_key_get(&sc->piano, sc->melody.notes[i].key)->x_mm;
        lo = fmin(lo, x), hi = fmax(hi, x);
    }
    if (!(lo <= hi)) lo = hi = 0;
    lo -= 90, hi += 90;
    double aspect = (double)sc->desc.width / sc->desc.height;
    double half_tan = tan(0.5 * CAMERA_FOV_DEG * SK_DEG_TO_RAD);
    double half_width = fmax(0.5 * (hi - lo), 160.0);
    double distance = fmax(half_width / (half_tan * aspect), 110.0 / half_tan);
    sk_vec3d target = {0.5 * (lo + hi), sc->piano.desc.white_top_mm + 20, sc->piano.desc.front_mm - 50};
    /* from the player's right, in front and above: the back of the hand, the keys and
       the forearm coming from the front */
    sk_vec3d dir = {0.45, 0.55, 0.70};
    double n = sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
    memset(camera, 0, sizeof *camera);
    camera->target[0] = (float)target.x, camera->target[1] = (float)target.y, camera->target[2] = (float)target.z;
    camera->position[0] = (float)(target.x + distance * dir.x / n);
    camera->position[1] = (float)(target.y + distance * dir.y / n);
    camera->position[2] = (float)(target.z + distance * dir.z / n);
    camera->fov = (float)(CAMERA_FOV_DEG * SK_DEG_TO_RAD);
}

static sk_result add_object(sk_render_scene_desc *d, const sk_render_object_desc *o, sk_error *err)
{
    if (d->object_count >= SK_RENDER_MAX_OBJECTS)
        return sk_fail(err, SK_ERROR_LIMIT, "stage: %d objects leave no room for the keys and the hand (at most %d in all)",
                       d->object_count, SK_RENDER_MAX_OBJECTS);
    d->objects[d->object_count++] = *o;
    return SK_OK;
}

static int add_material(sk_render_scene_desc *d, const sk_render_material_desc *m)
{
    if (d->material_count >= SK_RENDER_MAX_MATERIALS) return -1;
    d->materials[d->material_count] = *m;
    return d->material_count++;
}

/* The placement of a hand link in the scene as a render transform (centre `mid`). */
static sk_render_transform link_transform(const sk_mat3d *rot, sk_vec3d mid)
{
    /* columns of the link frame, turned into the scene */
    sk_mat3d r;
    for (int c = 0; c < 3; c++) {
        sk_vec3d col = sk__hand_to_scene((sk_vec3d){rot->m[0][c], rot->m[1][c], rot->m[2][c]});
        r.m[0][c] = col.x, r.m[1][c] = col.y, r.m[2][c] = col.z;
    }
    double x, y, z;
    sk_hand_euler321_from_matrix(r, &x, &y, &z);
    sk_vec3d p = sk__hand_to_scene(mid);
    sk_render_transform t = {{(float)p.x, (float)p.y, (float)p.z}, {(float)x, (float)y, (float)z}, {0, 0, 0}};
    return t;
}

/* The hand as capsules along its links and a box for the palm. */
static sk_result add_hand(const sk_showcase *sc, const sk_showcase_pose *pose, sk_render_scene_desc *d, sk_error *err)
{
    sk_render_material_desc m = {0};
    snprintf(m.name, sizeof m.name, "showcase-hand");
    m.albedo[0] = 0.72f, m.albedo[1] = 0.52f, m.albedo[2] = 0.42f;
    m.specular = 0.08f;
    m.shininess = 30;
    if (add_material(d, &m) < 0) return sk_fail(err, SK_ERROR_LIMIT, "stage: no room for the hand's material");
    const sk_hand_frames *fr = &pose->frames;
    sk_result r = SK_OK;
    for (int l = 1; l < SK_HAND_LINK_COUNT && r == SK_OK; l++) {
        int a = sk_hand_link_point(l), b = sk_hand_link_end_point(l);
        sk_vec3d pa = fr->point[a], pb = fr->point[b];
        double len = sqrt((pb.x - pa.x) * (pb.x - pa.x) + (pb.y - pa.y) * (pb.y - pa.y) + (pb.z - pa.z) * (pb.z - pa.z));
        int finger = l <= 3 ? 0 : (l - 4) / 4 + 1, seg = l <= 3 ? l : (l - 4) % 4; /* seg 0 metacarpal */
        if (finger > 0 && seg == 0) continue; /* the palm box covers the metacarpals */
        double rad = sc->rig.tip_radius[finger] * (seg == 3 ? 1.0 : seg == 2 ? 1.12 : 1.25);
        if (finger == 0 && seg == 1) rad = sc->rig.tip_radius[0] * 1.3;
        sk_render_object_desc o = {0};
        snprintf(o.name, sizeof o.name, "hand-%s", sk_hand_link_name(l));
        o.shape = SK_RENDER_SHAPE_CAPSULE;
        o.radius = (float)rad;
        double straight = len - (seg == 3 ? rad : 0);
        o.height = (float)fmax(straight, 1e-3);
        o.segments = 24;
        o.rings = 12;
        snprintf(o.material, sizeof o.material, "showcase-hand");
        sk_vec3d mid = {0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y), 0.5 * (pa.z + pb.z)};
        if (seg == 3) { /* the cap ends at the fingertip */
            double s = 0.5 * rad / len;
            mid.x -= s * (pb.x - pa.x), mid.y -= s * (pb.y - pa.y), mid.z -= s * (pb.z - pa.z);
        }
        o.transform = link_transform(&fr->rotation[l], mid);
        r = add_object(d, &o, err);
    }
    if (r != SK_OK) return r;
    /* the palm: from the wrist to the knuckles */
    sk_vec3d w = fr->point[0], k = fr->point[sk__tip_point(2) - 3]; /* M.MCP */
    sk_render_object_desc palm = {0};
    snprintf(palm.name, sizeof palm.name, "hand-palm");
    palm.shape = SK_RENDER_SHAPE_BOX;
    double length = sqrt((k.x - w.x) * (k.x - w.x) + (k.y - w.y) * (k.y - w.y) + (k.z - w.z) * (k.z - w.z));
    palm.size[0] = (float)(0.9 * sc->skeleton.hand_breadth_mm), palm.size[1] = (float)length, palm.size[2] = 26;
    snprintf(palm.material, sizeof palm.material, "showcase-hand");
    palm.transform = link_transform(&fr->rotation[0], (sk_vec3d){0.5 * (w.x + k.x), 0.5 * (w.y + k.y), 0.5 * (w.z + k.z)});
    return add_object(d, &palm, err);
}

sk_result sk__scene_build(sk_showcase *sc, const sk_showcase_pose *pose, sk_render_scene_desc *d, sk_error *err)
{
    *d = *sc->stage;
    d->image.width = sc->desc.width;
    d->image.height = sc->desc.height;
    d->image.samples = sc->desc.samples;
    const sk_render_camera_desc *c = &sc->stage->camera;
    bool camera_set = false;
    for (int i = 0; i < 3; i++) camera_set = camera_set || c->position[i] != 0 || c->target[i] != 0;
    if (!camera_set) sk__scene_frame_camera(sc, &d->camera);
    sk_result r = SK_OK;
    for (int i = 0; i < SK_PIANO_KEY_COUNT && r == SK_OK; i++) {
        const sk_piano_key *k = &sc->piano.keys[i];
        sk_render_object_desc objects[2];
        const char *material = sc->stage->materials[k->black ? sc->ebony : sc->ivory].name;
        int n = sk_piano_key_objects(&sc->piano, k, pose->key_angle[i], material, objects);
        for (int j = 0; j < n && r == SK_OK; j++) r = add_object(d, &objects[j], err);
    }
    if (r == SK_OK) r = add_hand(sc, pose, d, err);
    return r;
}
