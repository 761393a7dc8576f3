/* A frame's render scene: the stage (cabinet, floor, lights), the 88 keys turned as the
 * pose says, the hand, and the camera framing the keys the melody plays. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "products/showcase/showcase_internal.h"

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
    sk_vec3d target = {0.5 * (lo + hi), sc->piano.desc.white_top_mm + 20,
                       sc->piano.desc.front_mm - 50};
    /* from the player's right, in front and above: the back of the hand, the keys and
       the forearm coming from the front */
    sk_vec3d dir = {0.45, 0.55, 0.70};
    double n = sqrt(dir.x * dir.x + dir.y * dir.y + dir.z * dir.z);
    memset(camera, 0, sizeof *camera);
    camera->target[0] = (float)target.x, camera->target[1] = (float)target.y,
    camera->target[2] = (float)target.z;
    camera->position[0] = (float)(target.x + distance * dir.x / n);
    camera->position[1] = (float)(target.y + distance * dir.y / n);
    camera->position[2] = (float)(target.z + distance * dir.z / n);
    camera->fov = (float)(CAMERA_FOV_DEG * SK_DEG_TO_RAD);
}

static sk_result add_object(sk_render_scene_desc *d, const sk_render_object_desc *o, sk_error *err)
{
    if (d->object_count >= SK_RENDER_MAX_OBJECTS)
        return sk_fail(
            err, SK_ERROR_LIMIT,
            "stage: %d objects leave no room for the keys and the hand (at most %d in all)",
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

/* The skin's shading, hand and forearm alike. */
static void skin_shading(sk_render_material_desc *m, const char *name)
{
    memset(m, 0, sizeof *m);
    snprintf(m->name, sizeof m->name, "%s", name);
    m->specular = 0.06f;
    m->shininess = 24;
    m->texture_weight = 0.7f;
}

/* The hand: its skinned surface with the baked texture, shaded as the thesis shades it
 * (a white surface's shading blended with the texture, 0.3 : 0.7, sec. 4.1.6). */
static sk_result add_hand(sk_showcase *sc, sk_render_scene_desc *d, const sk_mesh *mesh,
                          sk_error *err)
{
    sk_render_material_desc m;
    skin_shading(&m, "showcase-skin");
    m.albedo[0] = m.albedo[1] = m.albedo[2] = 1;
    m.albedo_image = sc->skin_albedo;
    m.normal_image = sc->skin_normal;
    if (add_material(d, &m) < 0)
        return sk_fail(err, SK_ERROR_LIMIT, "stage: no room for the hand's material");
    sk_render_object_desc o = {0};
    snprintf(o.name, sizeof o.name, "hand");
    o.shape = SK_RENDER_SHAPE_MESH;
    o.mesh = mesh;
    snprintf(o.material, sizeof o.material, "showcase-skin");
    return add_object(d, &o, err);
}

/* The forearm: its tissue skin in the hand's colour, shaded with the hand's blend, the
 * back of the hand's microrelief as its bump map. */
static sk_result add_forearm(sk_showcase *sc, sk_render_scene_desc *d, sk_error *err)
{
    if (!sc->forearm.sim) return SK_OK;
    sk_render_material_desc m;
    skin_shading(&m, "showcase-forearm");
    memcpy(m.albedo, sc->forearm_albedo, sizeof m.albedo);
    if (sc->desc.back_skin) {
        m.texture = sk__forearm_skin_texture;
        m.texture_user = (void *)&sc->forearm.relief;
    }
    if (add_material(d, &m) < 0)
        return sk_fail(err, SK_ERROR_LIMIT, "stage: no room for the forearm's material");
    sk_render_object_desc o = {0};
    snprintf(o.name, sizeof o.name, "forearm");
    o.shape = SK_RENDER_SHAPE_MESH;
    o.mesh = &sc->forearm.mesh;
    snprintf(o.material, sizeof o.material, "showcase-forearm");
    return add_object(d, &o, err);
}

sk_result sk__scene_build(sk_showcase *sc, const sk_showcase_pose *pose, const sk_mesh *hand,
                          sk_render_scene_desc *d, sk_error *err)
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
    if (r == SK_OK) r = add_hand(sc, d, hand, err);
    if (r == SK_OK) r = add_forearm(sc, d, err);
    return r;
}
