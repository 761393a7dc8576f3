/* A strict BVH reader (any hierarchy, any channel order) with its own forward
 * kinematics, so exported motion can be checked by reading it back. Errors name the
 * line. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "hand/hand_private.h"
#include "shitsukan/io.h"

typedef struct lexer {
    const char *p, *end;
    int line;
    char tok[128];
} lexer;

/* Next whitespace-separated token; false at the end. */
static bool next_token(lexer *lx)
{
    while (lx->p < lx->end && (*lx->p == ' ' || *lx->p == '\t' || *lx->p == '\r' || *lx->p == '\n')) {
        if (*lx->p == '\n') lx->line++;
        lx->p++;
    }
    if (lx->p >= lx->end) return false;
    size_t n = 0;
    while (lx->p < lx->end && !(*lx->p == ' ' || *lx->p == '\t' || *lx->p == '\r' || *lx->p == '\n')) {
        if (n + 1 < sizeof lx->tok) lx->tok[n++] = *lx->p;
        lx->p++;
    }
    lx->tok[n] = '\0';
    return true;
}

static sk_result expect(lexer *lx, const char *word, sk_error *err)
{
    if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found the end", lx->line, word);
    if (strcmp(lx->tok, word) != 0)
        return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found \"%s\"", lx->line, word, lx->tok);
    return SK_OK;
}

static sk_result read_number(lexer *lx, double *out, sk_error *err)
{
    if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: expected a number, found the end", lx->line);
    char *stop = NULL;
    errno = 0;
    double v = strtod(lx->tok, &stop);
    if (*stop != '\0' || errno == ERANGE || !isfinite(v))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: \"%s\" is not a finite number", lx->line, lx->tok);
    *out = v;
    return SK_OK;
}

static sk_result read_offset(lexer *lx, sk_vec3d *o, sk_error *err)
{
    sk_result r = expect(lx, "OFFSET", err);
    if (r == SK_OK) r = read_number(lx, &o->x, err);
    if (r == SK_OK) r = read_number(lx, &o->y, err);
    if (r == SK_OK) r = read_number(lx, &o->z, err);
    return r;
}

/* Reads a joint body after its name: { OFFSET CHANNELS children } */
static sk_result read_joint(lexer *lx, sk_bvh *b, int parent, const char *name, bool end_site,
                            int depth, sk_error *err)
{
    if (depth > 64) return sk_fail(err, SK_ERROR_LIMIT, "line %d: hierarchy deeper than 64", lx->line);
    if (b->joint_count >= SK_BVH_MAX_JOINTS)
        return sk_fail(err, SK_ERROR_LIMIT, "line %d: more than %d joints", lx->line, SK_BVH_MAX_JOINTS);
    int j = b->joint_count++;
    snprintf(b->name[j], sizeof b->name[j], "%.63s", name);
    b->parent[j] = parent;
    b->channel_first[j] = b->channels_per_frame;
    sk_result r = expect(lx, "{", err);
    if (r == SK_OK) r = read_offset(lx, &b->offset[j], err);
    if (r != SK_OK) return r;
    if (!end_site) {
        r = expect(lx, "CHANNELS", err);
        double count = 0;
        if (r == SK_OK) r = read_number(lx, &count, err);
        if (r != SK_OK) return r;
        if (count < 0 || count > 6 || count != floor(count))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: CHANNELS %g is not 0..6", lx->line, count);
        b->channel_count[j] = (int)count;
        for (int c = 0; c < (int)count; c++) {
            if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: missing channel name", lx->line);
            static const char *const names[6] = {"Xposition", "Yposition", "Zposition",
                                                 "Xrotation", "Yrotation", "Zrotation"};
            static const char codes[6] = {'x', 'y', 'z', 'X', 'Y', 'Z'};
            int k = -1;
            for (int i = 0; i < 6; i++)
                if (strcmp(lx->tok, names[i]) == 0) k = i;
            if (k < 0) return sk_fail(err, SK_ERROR_PARSE, "line %d: unknown channel \"%s\"", lx->line, lx->tok);
            b->channel[j][c] = codes[k];
        }
        b->channels_per_frame += (int)count;
    }
    for (;;) {
        if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: unclosed joint \"%s\"", lx->line, name);
        if (strcmp(lx->tok, "}") == 0) return SK_OK;
        if (end_site) return sk_fail(err, SK_ERROR_PARSE, "line %d: End Site with children", lx->line);
        if (strcmp(lx->tok, "JOINT") == 0) {
            if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: JOINT without a name", lx->line);
            char child[64];
            snprintf(child, sizeof child, "%.63s", lx->tok);
            r = read_joint(lx, b, j, child, false, depth + 1, err);
        } else if (strcmp(lx->tok, "End") == 0) {
            r = expect(lx, "Site", err);
            char child[80];
            snprintf(child, sizeof child, "%.58s_end", name);
            if (r == SK_OK) r = read_joint(lx, b, j, child, true, depth + 1, err);
        } else {
            return sk_fail(err, SK_ERROR_PARSE, "line %d: unexpected \"%s\" in joint \"%s\"", lx->line, lx->tok, name);
        }
        if (r != SK_OK) return r;
    }
}

static sk_result parse(lexer *lx, sk_bvh *b, sk_error *err)
{
    sk_result r = expect(lx, "HIERARCHY", err);
    if (r == SK_OK) r = expect(lx, "ROOT", err);
    if (r != SK_OK) return r;
    if (!next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: ROOT without a name", lx->line);
    char name[64];
    snprintf(name, sizeof name, "%.63s", lx->tok);
    r = read_joint(lx, b, -1, name, false, 0, err);
    if (r == SK_OK) r = expect(lx, "MOTION", err);
    if (r == SK_OK) r = expect(lx, "Frames:", err);
    double frames = 0, ft = 0;
    if (r == SK_OK) r = read_number(lx, &frames, err);
    if (r == SK_OK) r = expect(lx, "Frame", err);
    if (r == SK_OK) r = expect(lx, "Time:", err);
    if (r == SK_OK) r = read_number(lx, &ft, err);
    if (r != SK_OK) return r;
    if (frames < 0 || frames > 10000000 || frames != floor(frames))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: Frames: %g is not a count", lx->line, frames);
    size_t total;
    if (!sk_size_mul((size_t)frames, (size_t)b->channels_per_frame, &total) || total > ((size_t)1 << 28))
        return sk_fail(err, SK_ERROR_LIMIT, "%g frames x %d channels is too much motion", frames, b->channels_per_frame);
    b->frame_count = (int)frames;
    b->frame_time = ft;
    b->motion = malloc((total ? total : 1) * sizeof *b->motion);
    if (!b->motion) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    for (size_t i = 0; i < total; i++) {
        r = read_number(lx, &b->motion[i], err);
        if (r != SK_OK) return r;
    }
    if (next_token(lx)) return sk_fail(err, SK_ERROR_PARSE, "line %d: data after the last frame", lx->line);
    return SK_OK;
}

sk_result sk_bvh_parse(const char *text, size_t length, const char *source_name, sk_bvh *out,
                       sk_error *err)
{
    memset(out, 0, sizeof *out);
    lexer lx = {text, text + length, 1, {0}};
    sk_result r = parse(&lx, out, err);
    if (r != SK_OK) {
        sk_bvh_free(out);
        sk_error_prefix(err, r, "%s", source_name);
    }
    return r;
}

sk_result sk_bvh_load_file(const char *path, sk_bvh *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    memset(out, 0, sizeof *out);
    sk_result r = sk_read_file(path, SK_HAND_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_bvh_parse(text, size, path, out, err);
    free(text);
    return r;
}

void sk_bvh_free(sk_bvh *b)
{
    if (!b) return;
    free(b->motion);
    b->motion = NULL;
    b->frame_count = 0;
}

int sk_bvh_find(const sk_bvh *b, const char *name)
{
    for (int j = 0; j < b->joint_count; j++)
        if (strcmp(b->name[j], name) == 0) return j;
    return -1;
}

void sk_bvh_positions(const sk_bvh *b, int frame, sk_vec3d *out)
{
    sk_mat3d g[SK_BVH_MAX_JOINTS];
    const double *m = b->motion + (size_t)frame * b->channels_per_frame;
    for (int j = 0; j < b->joint_count; j++) {
        sk_vec3d t = b->offset[j];
        sk_mat3d r = sk_m3d_identity();
        for (int c = 0; c < b->channel_count[j]; c++) {
            double v = m[b->channel_first[j] + c];
            switch (b->channel[j][c]) {
            case 'x': t.x += v; break;
            case 'y': t.y += v; break;
            case 'z': t.z += v; break;
            case 'X': r = sk_m3d_mul(r, sk_m3d_rot_x(v * SK_DEG_TO_RAD)); break;
            case 'Y': r = sk_m3d_mul(r, sk_m3d_rot_y(v * SK_DEG_TO_RAD)); break;
            default: r = sk_m3d_mul(r, sk_m3d_rot_z(v * SK_DEG_TO_RAD)); break;
            }
        }
        int p = b->parent[j];
        if (p < 0) {
            g[j] = r;
            out[j] = t;
        } else {
            g[j] = sk_m3d_mul(g[p], r);
            out[j] = sk_v3d_add(out[p], sk_m3d_apply(g[p], t));
        }
    }
}
