/* A strict BVH reader (any hierarchy, several ROOTs, per-joint channel order, End Site,
 * LF or CRLF, tabs or spaces) with its own forward kinematics. Errors name the line.
 * Form of the format: include/shitsukan/bvh.h (after Meredith & Maddock 2001). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "base/io_internal.h"
#include "shitsukan/bvh.h"
#include "shitsukan/io.h"

typedef struct lexer {
    const char *p, *end;
    int line;        /* line of the reading position */
    int tok_line;    /* line of the current (last read) token, for messages */
    const char *tok; /* the current token (not NUL-terminated) */
    size_t len;
} lexer;

static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/* Next whitespace-separated token; false at the end. */
static bool next_token(lexer *lx)
{
    while (lx->p < lx->end && is_space(*lx->p)) {
        if (*lx->p == '\n') lx->line++;
        lx->p++;
    }
    if (lx->p >= lx->end) return false;
    lx->tok = lx->p;
    lx->tok_line = lx->line;
    while (lx->p < lx->end && !is_space(*lx->p)) lx->p++;
    lx->len = (size_t)(lx->p - lx->tok);
    return true;
}

static bool token_is(const lexer *lx, const char *word)
{
    return lx->len == strlen(word) && memcmp(lx->tok, word, lx->len) == 0;
}

/* The current token for a message: at most 40 bytes, control bytes shown as '?'. */
static const char *shown(const lexer *lx, char buf[48])
{
    size_t n = lx->len < 40 ? lx->len : 40;
    for (size_t i = 0; i < n; i++) {
        unsigned char c = (unsigned char)lx->tok[i];
        buf[i] = (c < 32 || c > 126) ? '?' : (char)c;
    }
    if (lx->len > 40)
        memcpy(buf + n, "...", 4);
    else
        buf[n] = '\0';
    return buf;
}

static sk_result expect(lexer *lx, const char *word, sk_error *err)
{
    char buf[48];
    if (!next_token(lx))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found the end", lx->tok_line,
                       word);
    if (!token_is(lx, word))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found \"%s\"", lx->tok_line,
                       word, shown(lx, buf));
    return SK_OK;
}

/* The current token as a finite number. */
static sk_result token_number(lexer *lx, double *out, sk_error *err)
{
    char buf[48];
    double v;
    if (!sk__parse_double(lx->tok, lx->len, &v) || !isfinite(v))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: \"%s\" is not a finite number", lx->tok_line,
                       shown(lx, buf));
    *out = v;
    return SK_OK;
}

static sk_result read_number(lexer *lx, const char *what, double *out, sk_error *err)
{
    if (!next_token(lx))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: expected %s, found the end", lx->tok_line,
                       what);
    return token_number(lx, out, err);
}

static sk_result read_offset(lexer *lx, sk_vec3d *o, sk_error *err)
{
    sk_result r = expect(lx, "OFFSET", err);
    if (r == SK_OK) r = read_number(lx, "an OFFSET number", &o->x, err);
    if (r == SK_OK) r = read_number(lx, "an OFFSET number", &o->y, err);
    if (r == SK_OK) r = read_number(lx, "an OFFSET number", &o->z, err);
    return r;
}

static sk_result read_channels(lexer *lx, sk_bvh *b, int j, sk_error *err)
{
    static const char *const names[6] = {"Xposition", "Yposition", "Zposition",
                                         "Xrotation", "Yrotation", "Zrotation"};
    static const char codes[6] = {'x', 'y', 'z', 'X', 'Y', 'Z'};
    char buf[48];
    sk_result r = expect(lx, "CHANNELS", err);
    double count = 0;
    if (r == SK_OK) r = read_number(lx, "a channel count", &count, err);
    if (r != SK_OK) return r;
    if (count < 0 || count > 6 || count != floor(count))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: CHANNELS %g is not a count 0..6",
                       lx->tok_line, count);
    b->channel_count[j] = (int)count;
    for (int c = 0; c < (int)count; c++) {
        if (!next_token(lx))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: expected a channel name, found the end",
                           lx->tok_line);
        int k = -1;
        for (int i = 0; i < 6; i++)
            if (token_is(lx, names[i])) k = i;
        if (k < 0)
            return sk_fail(err, SK_ERROR_PARSE, "line %d: unknown channel \"%s\"", lx->tok_line,
                           shown(lx, buf));
        if (memchr(b->channel[j], codes[k], (size_t)c))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: channel \"%s\" twice", lx->tok_line,
                           names[k]);
        b->channel[j][c] = codes[k];
    }
    b->channels_per_frame += (int)count;
    return SK_OK;
}

static sk_result add_joint(lexer *lx, sk_bvh *b, int parent, const char *name, size_t name_len,
                           bool end_site, int *out, sk_error *err)
{
    if (b->joint_count >= SK_BVH_MAX_JOINTS)
        return sk_fail(err, SK_ERROR_LIMIT, "line %d: more than %d joints and end sites",
                       lx->tok_line, SK_BVH_MAX_JOINTS);
    if (name_len >= SK_BVH_NAME_SIZE)
        return sk_fail(err, SK_ERROR_PARSE, "line %d: joint name longer than %d bytes",
                       lx->tok_line, SK_BVH_NAME_SIZE - 1);
    /* a control byte (a NUL above all) would cut or garble the name when written again */
    for (size_t i = 0; i < name_len; i++) {
        unsigned char c = (unsigned char)name[i];
        if (c < 32 || c == 127)
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d: joint name with a control byte (0x%02x) at byte %zu",
                           lx->tok_line, c, i + 1);
    }
    int j = b->joint_count++;
    memcpy(b->name[j], name, name_len);
    b->name[j][name_len] = '\0';
    if (!end_site)
        for (int k = 0; k < j; k++)
            if (!b->end_site[k] && strcmp(b->name[k], b->name[j]) == 0)
                return sk_fail(err, SK_ERROR_PARSE, "line %d: joint \"%s\" twice", lx->tok_line,
                               b->name[j]);
    b->parent[j] = parent;
    b->end_site[j] = end_site;
    b->channel_first[j] = b->channels_per_frame;
    *out = j;
    return SK_OK;
}

/* Reads a joint body after its name: { OFFSET CHANNELS children } */
static sk_result read_joint(lexer *lx, sk_bvh *b, int parent, const char *name, size_t name_len,
                            bool end_site, int depth, sk_error *err)
{
    if (depth >= SK_BVH_MAX_DEPTH)
        return sk_fail(err, SK_ERROR_LIMIT, "line %d: hierarchy deeper than %d", lx->tok_line,
                       SK_BVH_MAX_DEPTH);
    int j = 0;
    sk_result r = add_joint(lx, b, parent, name, name_len, end_site, &j, err);
    if (r == SK_OK) r = expect(lx, "{", err);
    if (r == SK_OK) r = read_offset(lx, &b->offset[j], err);
    if (r == SK_OK && !end_site) r = read_channels(lx, b, j, err);
    if (r != SK_OK) return r;
    char buf[48];
    for (;;) {
        if (!next_token(lx))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: joint \"%s\" is not closed (no \"}\")",
                           lx->tok_line, b->name[j]);
        if (token_is(lx, "}")) return SK_OK;
        if (token_is(lx, "MOTION"))
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d: joint \"%s\" is not closed (no \"}\" before MOTION)",
                           lx->tok_line, b->name[j]);
        if (end_site)
            return sk_fail(err, SK_ERROR_PARSE, "line %d: End Site with children", lx->tok_line);
        if (token_is(lx, "JOINT")) {
            if (!next_token(lx))
                return sk_fail(err, SK_ERROR_PARSE, "line %d: JOINT without a name", lx->tok_line);
            if (token_is(lx, "{"))
                return sk_fail(err, SK_ERROR_PARSE, "line %d: JOINT without a name", lx->tok_line);
            r = read_joint(lx, b, j, lx->tok, lx->len, false, depth + 1, err);
        } else if (token_is(lx, "End")) {
            if (!next_token(lx) || lx->len != 4 || strncasecmp(lx->tok, "Site", 4) != 0)
                return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"Site\" after \"End\"",
                               lx->tok_line);
            char child[SK_BVH_NAME_SIZE];
            int n = snprintf(child, sizeof child, "%.*s_end", SK_BVH_NAME_SIZE - 5, b->name[j]);
            r = read_joint(lx, b, j, child, (size_t)n, true, depth + 1, err);
        } else {
            return sk_fail(err, SK_ERROR_PARSE, "line %d: unexpected \"%s\" in joint \"%s\"",
                           lx->tok_line, shown(lx, buf), b->name[j]);
        }
        if (r != SK_OK) return r;
    }
}

static sk_result read_motion(lexer *lx, sk_bvh *b, sk_error *err)
{
    double frames = 0, ft = 0;
    sk_result r = expect(lx, "Frames:", err);
    if (r == SK_OK) r = read_number(lx, "the frame count", &frames, err);
    if (r != SK_OK) return r;
    int frames_line = lx->tok_line;
    if (frames < 0 || frames > 1e9 || frames != floor(frames))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: Frames: %g is not a count", lx->tok_line,
                       frames);
    r = expect(lx, "Frame", err);
    if (r == SK_OK) r = expect(lx, "Time:", err);
    if (r == SK_OK) r = read_number(lx, "the frame time", &ft, err);
    if (r != SK_OK) return r;
    if (!(ft > 0.0))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: Frame Time: %g must be positive (seconds)",
                       lx->tok_line, ft);
    /* Every number takes at least one byte and one separator, so the rest of the text
       bounds what a truthful header can ask for; size the motion by that. */
    size_t total, rest = (size_t)(lx->end - lx->p);
    size_t holds = rest / 2 + 1;
    if (!sk_size_mul((size_t)frames, (size_t)b->channels_per_frame, &total) || total > holds)
        return sk_fail(
            err, SK_ERROR_PARSE,
            "line %d: truncated: %.0f frames x %d channels need %.0f numbers, the rest of "
            "the file (%zu bytes) holds at most %zu",
            frames_line, frames, b->channels_per_frame, frames * b->channels_per_frame, rest,
            holds);
    b->frame_count = (int)frames;
    b->frame_time = ft;
    b->motion = malloc((total ? total : 1) * sizeof *b->motion);
    if (!b->motion)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu motion values", total);
    for (size_t i = 0; i < total; i++) {
        if (!next_token(lx)) {
            size_t c = (size_t)b->channels_per_frame;
            return sk_fail(err, SK_ERROR_PARSE,
                           "line %d: truncated: frame %zu of %d ends after %zu of its %zu numbers",
                           lx->tok_line, i / c + 1, b->frame_count, i % c, c);
        }
        r = token_number(lx, &b->motion[i], err);
        if (r != SK_OK) return r;
    }
    if (next_token(lx))
        return sk_fail(err, SK_ERROR_PARSE, "line %d: data after the last frame", lx->tok_line);
    return SK_OK;
}

static sk_result parse(lexer *lx, sk_bvh *b, sk_error *err)
{
    sk_result r = expect(lx, "HIERARCHY", err);
    if (r != SK_OK) return r;
    bool any = false;
    for (;;) {
        if (!next_token(lx))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found the end",
                           lx->tok_line, any ? "MOTION" : "ROOT");
        if (any && token_is(lx, "MOTION")) break;
        if (!token_is(lx, "ROOT")) {
            char buf[48];
            return sk_fail(err, SK_ERROR_PARSE, "line %d: expected \"%s\", found \"%s\"",
                           lx->tok_line, any ? "MOTION" : "ROOT", shown(lx, buf));
        }
        if (!next_token(lx) || token_is(lx, "{"))
            return sk_fail(err, SK_ERROR_PARSE, "line %d: ROOT without a name", lx->tok_line);
        r = read_joint(lx, b, -1, lx->tok, lx->len, false, 0, err);
        if (r != SK_OK) return r;
        any = true;
    }
    return read_motion(lx, b, err);
}

sk_result sk_bvh_parse(const char *text, size_t length, const char *source_name, sk_bvh *out,
                       sk_error *err)
{
    sk_bvh_init(out);
    if (!text) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "BVH text is NULL");
    lexer lx = {text, text + length, 1, 1, text, 0};
    sk__c_locale locale;
    sk__c_locale_push(&locale);
    sk_result r = parse(&lx, out, err);
    sk__c_locale_pop(&locale);
    if (r != SK_OK) {
        sk_bvh_free(out);
        sk_error_prefix(err, r, "%s", source_name ? source_name : "BVH");
    }
    return r;
}

sk_result sk_bvh_load_file(const char *path, sk_bvh *out, sk_error *err)
{
    char *text = NULL;
    size_t size = 0;
    sk_bvh_init(out);
    sk_result r = sk_read_file(path, SK_BVH_MAX_FILE_BYTES, &text, &size, err);
    if (r != SK_OK) return r;
    r = sk_bvh_parse(text, size, path, out, err);
    free(text);
    return r;
}
