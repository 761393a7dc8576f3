/* Built-in primitives (plane, box, sphere, cylinder, capsule) as triangle meshes with
 * normals, UVs and tangents. Round shapes are surfaces of revolution about y built from a
 * profile curve, so UVs follow arc length (u around at the widest radius, v along the
 * profile) and tangents are exact. */
#include <math.h>
#include <string.h>

#include "render/render_internal.h"

#define DEFAULT_SEGMENTS 64
#define DEFAULT_RINGS 32
#define MAX_PRIMITIVE_VERTICES (1u << 23)

/* A mesh being filled: counters into sk_mesh arrays. */
typedef struct builder {
    sk_mesh *mesh;
    float *tangents;
    size_t nv, nt;
} builder;

static size_t add_vertex(builder *b, sk_vec3f p, sk_vec3f n, sk_vec3f t, float u, float v)
{
    size_t i = b->nv++;
    float *pp = b->mesh->positions + 3 * i, *np = b->mesh->normals + 3 * i;
    float *uv = b->mesh->uvs + 2 * i, *tp = b->tangents + 4 * i;
    pp[0] = p.x, pp[1] = p.y, pp[2] = p.z;
    np[0] = n.x, np[1] = n.y, np[2] = n.z;
    uv[0] = u, uv[1] = v;
    tp[0] = t.x, tp[1] = t.y, tp[2] = t.z, tp[3] = 1.0f; /* every primitive is right-handed */
    return i;
}

/* Adds a triangle wound counter-clockwise seen from the side its vertex normals face. */
static void add_triangle(builder *b, size_t a, size_t c, size_t d)
{
    const float *p = b->mesh->positions, *n = b->mesh->normals;
    sk_vec3f pa = sk_v3f_load(p + 3 * a), pc = sk_v3f_load(p + 3 * c), pd = sk_v3f_load(p + 3 * d);
    sk_vec3f face = sk_v3f_cross(sk_v3f_sub(pc, pa), sk_v3f_sub(pd, pa));
    sk_vec3f ns = sk_v3f_add(sk_v3f_add(sk_v3f_load(n + 3 * a), sk_v3f_load(n + 3 * c)),
                             sk_v3f_load(n + 3 * d));
    uint32_t *ix = b->mesh->indices + 3 * b->nt++;
    ix[0] = (uint32_t)a;
    if (sk_v3f_dot(face, ns) >= 0.0f) {
        ix[1] = (uint32_t)c, ix[2] = (uint32_t)d;
    } else {
        ix[1] = (uint32_t)d, ix[2] = (uint32_t)c;
    }
}

/* A flat rectangle centred at `centre` with unit normal n, tangent t and bitangent bt
 * (t x bt = n) and half extents ht, hb along them. */
static void add_quad(builder *b, sk_vec3f centre, sk_vec3f n, sk_vec3f t, sk_vec3f bt, float ht,
                     float hb, bool unit_uv)
{
    size_t v[4];
    static const float corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; k++) {
        float a = corner[k][0] * ht, c = corner[k][1] * hb;
        sk_vec3f p = sk_v3f_add(centre, sk_v3f_add(sk_v3f_scale(t, a), sk_v3f_scale(bt, c)));
        float u = a + ht, w = c + hb;
        if (unit_uv) u /= 2.0f * ht, w /= 2.0f * hb;
        v[k] = add_vertex(b, p, n, t, u, w);
    }
    add_triangle(b, v[0], v[1], v[2]);
    add_triangle(b, v[0], v[2], v[3]);
}

/* A point of a profile curve in the (rho, y) half plane with its outward unit normal and
 * the arc length from the profile's start. */
typedef struct profile_point {
    float rho, y;
    float n_rho, n_y;
    float s;
} profile_point;

/* Revolves a profile (bottom to top) about +y: P = (rho sin phi, y, rho cos phi) with phi
 * from -pi to pi, so the seam (u = 0) is at the back (-z) and the front (+z, towards the
 * default camera) has its tangent along +x. */
static void revolve(builder *b, const profile_point *prof, int count, int segments, float u_len,
                    float v_len, bool unit_uv)
{
    size_t ring_start[4096 + 8];
    for (int j = 0; j < count; j++) {
        const profile_point *q = &prof[j];
        float v = unit_uv ? q->s / v_len : q->s;
        ring_start[j] = b->nv;
        bool pole = q->rho == 0.0f;
        int n_vert = pole ? segments : segments + 1;
        for (int k = 0; k < n_vert; k++) {
            /* poles carry one vertex per segment at its middle angle */
            float f = ((float)k + (pole ? 0.5f : 0.0f)) / (float)segments;
            float phi = -SK_PI_F + 2.0f * SK_PI_F * f;
            float sp = sinf(phi), cp = cosf(phi);
            sk_vec3f p = sk_v3f(q->rho * sp, q->y, q->rho * cp);
            sk_vec3f n = sk_v3f(q->n_rho * sp, q->n_y, q->n_rho * cp);
            sk_vec3f t = sk_v3f(cp, 0.0f, -sp);
            add_vertex(b, p, n, t, unit_uv ? f : f * u_len, v);
        }
    }
    for (int j = 0; j + 1 < count; j++) {
        bool pole0 = prof[j].rho == 0.0f, pole1 = prof[j + 1].rho == 0.0f;
        size_t r0 = ring_start[j], r1 = ring_start[j + 1];
        for (int k = 0; k < segments; k++) {
            size_t a = r0 + (size_t)k, c = r0 + (size_t)k + 1;
            size_t d = r1 + (size_t)k, e = r1 + (size_t)k + 1;
            if (pole0 && pole1) continue;
            if (pole0) {
                add_triangle(b, a, e, d);
            } else if (pole1) {
                add_triangle(b, a, c, d);
            } else {
                add_triangle(b, a, c, e);
                add_triangle(b, a, e, d);
            }
        }
    }
}

/* A flat disk cap at height y facing up (+y) or down. */
static void add_cap(builder *b, float radius, float y, bool up, int segments, bool unit_uv)
{
    sk_vec3f n = sk_v3f(0.0f, up ? 1.0f : -1.0f, 0.0f);
    sk_vec3f t = sk_v3f(1.0f, 0.0f, 0.0f);
    float zsign = up ? -1.0f : 1.0f; /* v runs along -z on top, +z below (t x bt = n) */
    float scale = unit_uv ? 1.0f / (2.0f * radius) : 1.0f;
    size_t centre = add_vertex(b, sk_v3f(0.0f, y, 0.0f), n, t, radius * scale, radius * scale);
    size_t first = b->nv;
    for (int k = 0; k <= segments; k++) {
        float phi = -SK_PI_F + 2.0f * SK_PI_F * (float)k / (float)segments;
        float x = radius * sinf(phi), z = radius * cosf(phi);
        add_vertex(b, sk_v3f(x, y, z), n, t, (x + radius) * scale, (zsign * z + radius) * scale);
    }
    for (int k = 0; k < segments; k++)
        add_triangle(b, centre, first + (size_t)k, first + (size_t)k + 1);
}

/* Points of a quarter circle of radius r centred at (0, yc), latitude lat0 -> lat1. */
static int arc_points(profile_point *out, float r, float yc, float lat0, float lat1, int steps,
                      float s0, bool skip_first)
{
    int n = 0;
    for (int i = skip_first ? 1 : 0; i <= steps; i++) {
        float lat = lat0 + (lat1 - lat0) * (float)i / (float)steps;
        profile_point *q = &out[n++];
        q->n_rho = cosf(lat);
        q->n_y = sinf(lat);
        /* exact zero at the poles so they become single points */
        if (fabsf(lat) >= SK_PI_F / 2.0f - 1e-6f) q->n_rho = 0.0f, q->n_y = lat > 0 ? 1.0f : -1.0f;
        q->rho = r * q->n_rho;
        q->y = yc + r * q->n_y;
        q->s = s0 + r * fabsf(lat - lat0);
    }
    return n;
}

static sk_result check_size(const char *what, size_t vertices, sk_error *err)
{
    if (vertices > MAX_PRIMITIVE_VERTICES)
        return sk_fail(err, SK_ERROR_LIMIT,
                       "%s: %zu vertices exceed the limit of %u (lower segments or rings)", what,
                       vertices, MAX_PRIMITIVE_VERTICES);
    return SK_OK;
}

sk_result sk_render_make_primitive(const sk_render_object_desc *object, sk_mesh *mesh,
                                   sk_error *err)
{
    memset(mesh, 0, sizeof *mesh);
    int segments = object->segments > 0 ? object->segments : DEFAULT_SEGMENTS;
    int rings = object->rings > 0 ? object->rings : DEFAULT_RINGS;
    if (segments < 3 || segments > 4096)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "segments = %d is out of range [3, 4096]",
                       segments);
    if (rings < 2 || rings > 4096)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "rings = %d is out of range [2, 4096]",
                       rings);
    float sx = object->size[0], sy = object->size[1], sz = object->size[2];
    if (sx == 0 && sy == 0 && sz == 0) sx = sy = sz = 1.0f;
    float radius = object->radius > 0 ? object->radius : 0.5f;
    float height = object->height > 0 ? object->height : 1.0f;
    bool unit_uv = object->uv == SK_RENDER_UV_UNIT;

    size_t nv = 0, nt = 0;
    profile_point prof[4096 + 8];
    int count = 0;
    float u_len = 2.0f * SK_PI_F * radius, v_len = 1.0f;
    switch (object->shape) {
    case SK_RENDER_SHAPE_PLANE:
        if (!(sx > 0 && sz > 0))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "size = [%g, %g, %g]: a plane needs size[0] > 0 and size[2] > 0", sx, sy,
                           sz);
        nv = 4, nt = 2;
        break;
    case SK_RENDER_SHAPE_BOX:
        if (!(sx > 0 && sy > 0 && sz > 0))
            return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                           "size = [%g, %g, %g]: a box needs every edge > 0", sx, sy, sz);
        nv = 24, nt = 12;
        break;
    case SK_RENDER_SHAPE_SPHERE:
        count = arc_points(prof, radius, 0.0f, -SK_PI_F / 2, SK_PI_F / 2, rings, 0.0f, false);
        v_len = SK_PI_F * radius;
        break;
    case SK_RENDER_SHAPE_CYLINDER:
        prof[0] = (profile_point){radius, -height / 2, 1.0f, 0.0f, 0.0f};
        prof[1] = (profile_point){radius, height / 2, 1.0f, 0.0f, height};
        count = 2;
        v_len = height;
        break;
    case SK_RENDER_SHAPE_CAPSULE: {
        int half = rings / 2 > 0 ? rings / 2 : 1;
        count = arc_points(prof, radius, -height / 2, -SK_PI_F / 2, 0.0f, half, 0.0f, false);
        float s_top = SK_PI_F * radius / 2 + height;
        count +=
            arc_points(prof + count, radius, height / 2, 0.0f, SK_PI_F / 2, half, s_top, false);
        v_len = SK_PI_F * radius + height;
        break;
    }
    default:
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "shape %d is not a built-in primitive",
                       (int)object->shape);
    }
    if (count > 0) {
        nv = (size_t)count * (size_t)(segments + 1);
        nt = 2 * (size_t)(count - 1) * (size_t)segments;
        if (object->shape == SK_RENDER_SHAPE_CYLINDER) {
            nv += 2 * (size_t)(segments + 2);
            nt += 2 * (size_t)segments;
        }
    }
    sk_result r = check_size("primitive", nv, err);
    if (r != SK_OK) return r;
    if ((r = sk_mesh_create(mesh, nv, nt, SK_MESH_NORMALS | SK_MESH_UVS, err)) != SK_OK) return r;
    builder b = {mesh, NULL, 0, 0};
    if ((r = sk_mesh_add_attribute(mesh, "tangent", 4, &b.tangents, err)) != SK_OK) {
        sk_mesh_free(mesh);
        return r;
    }

    sk_vec3f X = sk_v3f(1, 0, 0), Y = sk_v3f(0, 1, 0), Z = sk_v3f(0, 0, 1);
    switch (object->shape) {
    case SK_RENDER_SHAPE_PLANE:
        add_quad(&b, sk_v3f(0, 0, 0), Y, X, sk_v3f_neg(Z), sx / 2, sz / 2, unit_uv);
        break;
    case SK_RENDER_SHAPE_BOX: {
        float hx = sx / 2, hy = sy / 2, hz = sz / 2;
        add_quad(&b, sk_v3f(hx, 0, 0), X, sk_v3f_neg(Z), Y, hz, hy, unit_uv);
        add_quad(&b, sk_v3f(-hx, 0, 0), sk_v3f_neg(X), Z, Y, hz, hy, unit_uv);
        add_quad(&b, sk_v3f(0, hy, 0), Y, X, sk_v3f_neg(Z), hx, hz, unit_uv);
        add_quad(&b, sk_v3f(0, -hy, 0), sk_v3f_neg(Y), X, Z, hx, hz, unit_uv);
        add_quad(&b, sk_v3f(0, 0, hz), Z, X, Y, hx, hy, unit_uv);
        add_quad(&b, sk_v3f(0, 0, -hz), sk_v3f_neg(Z), sk_v3f_neg(X), Y, hx, hy, unit_uv);
        break;
    }
    default:
        revolve(&b, prof, count, segments, u_len, v_len, unit_uv);
        if (object->shape == SK_RENDER_SHAPE_CYLINDER) {
            add_cap(&b, radius, height / 2, true, segments, unit_uv);
            add_cap(&b, radius, -height / 2, false, segments, unit_uv);
        }
        break;
    }
    /* poles use one vertex fewer per ring and skip degenerate triangles */
    mesh->vertex_count = b.nv;
    mesh->triangle_count = b.nt;
    return SK_OK;
}
