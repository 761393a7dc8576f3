/* Request parsing, path mapping and MIME types of the studio's HTTP server (pure
 * functions, fuzzed by fuzz/fuzz_http_request.c). */
#include <string.h>

#include "http.h"

static int hex_value(char c)
{
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

static bool is_token_char(char c)
{
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' ||
           c == '_';
}

/* Percent-decodes a request target's path part into out; false if malformed. */
static bool decode_path(const char *s, size_t n, char *out, size_t size, bool *too_long)
{
    size_t k = 0;
    *too_long = false;
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        if (c == '?' || c == '#') break;
        if (c == '%') {
            if (i + 2 >= n) return false;
            int hi = hex_value(s[i + 1]), lo = hex_value(s[i + 2]);
            if (hi < 0 || lo < 0) return false;
            c = (char)(hi * 16 + lo);
            if (c == '\0') return false;
            i += 2;
        } else if ((unsigned char)c <= 0x20 || c == 0x7f) {
            return false;
        }
        if (k + 1 >= size) {
            *too_long = true;
            return false;
        }
        out[k++] = c;
    }
    out[k] = '\0';
    return k > 0 && out[0] == '/';
}

http_parse_status http_parse_request(const char *data, size_t size, http_request *out)
{
    memset(out, 0, sizeof *out);
    /* the head ends at the first blank line (CRLF CRLF, or bare LF LF) */
    size_t end = 0;
    for (size_t i = 0; i + 1 < size && i < HTTP_MAX_HEAD; i++) {
        if (data[i] == '\n' && data[i + 1] == '\n') {
            end = i + 2;
            break;
        }
        if (i + 3 < size && data[i] == '\r' && data[i + 1] == '\n' && data[i + 2] == '\r' &&
            data[i + 3] == '\n') {
            end = i + 4;
            break;
        }
    }
    if (end == 0) return size >= HTTP_MAX_HEAD ? HTTP_PARSE_TOO_LARGE : HTTP_PARSE_INCOMPLETE;
    out->head_bytes = end;
    for (size_t i = 0; i < end; i++)
        if (data[i] == '\0') return HTTP_PARSE_BAD;
    /* request line: METHOD SP target SP HTTP/1.x */
    size_t line = 0;
    while (line < end && data[line] != '\r' && data[line] != '\n') line++;
    size_t m = 0;
    while (m < line && is_token_char(data[m])) m++;
    if (m == 0 || m >= sizeof out->method || m >= line || data[m] != ' ') return HTTP_PARSE_BAD;
    memcpy(out->method, data, m);
    out->method[m] = '\0';
    size_t t0 = m + 1, t1 = t0;
    while (t1 < line && data[t1] != ' ') t1++;
    if (t1 == t0 || t1 >= line) return HTTP_PARSE_BAD;
    const char *version = data + t1 + 1;
    size_t vlen = line - t1 - 1;
    if (vlen != 8 || memcmp(version, "HTTP/1.", 7) != 0) {
        if (vlen >= 5 && memcmp(version, "HTTP/", 5) == 0) return HTTP_PARSE_VERSION;
        return HTTP_PARSE_BAD;
    }
    if (version[7] != '0' && version[7] != '1') return HTTP_PARSE_VERSION;
    out->minor_version = version[7] - '0';
    bool too_long;
    if (!decode_path(data + t0, t1 - t0, out->path, sizeof out->path, &too_long))
        return too_long ? HTTP_PARSE_URI_TOO_LONG : HTTP_PARSE_BAD;
    /* header lines: name ":" value, no obsolete line folding */
    size_t p = line;
    while (p < end) {
        if (data[p] == '\r') p++;
        if (p < end && data[p] == '\n') p++;
        size_t q = p;
        while (q < end && data[q] != '\r' && data[q] != '\n') q++;
        if (q == p) break; /* the blank line */
        if (data[p] == ' ' || data[p] == '\t') return HTTP_PARSE_BAD;
        const char *colon = memchr(data + p, ':', q - p);
        if (!colon || colon == data + p) return HTTP_PARSE_BAD;
        for (const char *c = data + p; c < colon; c++)
            if (!is_token_char(*c) && *c != '.' && *c != '!' && *c != '+') return HTTP_PARSE_BAD;
        p = q;
    }
    return HTTP_PARSE_OK;
}

bool http_relative_path(const char *path, char *out, size_t size)
{
    if (!path || path[0] != '/' || size < 16) return false;
    size_t k = 0;
    const char *s = path + 1;
    while (*s) {
        const char *e = strchr(s, '/');
        size_t n = e ? (size_t)(e - s) : strlen(s);
        if (n == 0) return false;      /* "//" */
        if (s[0] == '.') return false; /* ".", "..", hidden files */
        for (size_t i = 0; i < n; i++) {
            unsigned char c = (unsigned char)s[i];
            if (c < 0x20 || c == 0x7f || c == '\\' || c == ':') return false;
        }
        if (k + n + 2 >= size) return false;
        memcpy(out + k, s, n);
        k += n;
        if (!e) break;
        out[k++] = '/';
        s = e + 1;
    }
    out[k] = '\0';
    /* "/" or ".../": the folder's index */
    if (k == 0 || out[k - 1] == '/') {
        const char *index = "index.html";
        if (k + strlen(index) + 1 > size) return false;
        memcpy(out + k, index, strlen(index) + 1);
    }
    return true;
}

const char *http_mime_type(const char *path)
{
    static const char *const table[][2] = {
        {".html", "text/html; charset=utf-8"},
        {".js", "text/javascript; charset=utf-8"},
        {".mjs", "text/javascript; charset=utf-8"},
        {".css", "text/css; charset=utf-8"},
        {".json", "application/json; charset=utf-8"},
        {".wasm", "application/wasm"},
        {".png", "image/png"},
        {".jpg", "image/jpeg"},
        {".svg", "image/svg+xml"},
        {".ico", "image/x-icon"},
        {".txt", "text/plain; charset=utf-8"},
        {".md", "text/plain; charset=utf-8"},
        {".bvh", "text/plain; charset=utf-8"},
        {".csv", "text/csv; charset=utf-8"},
        {".exr", "image/x-exr"},
        {".glb", "model/gltf-binary"},
    };
    const char *dot = strrchr(path, '.');
    const char *slash = strrchr(path, '/');
    if (dot && (!slash || dot > slash))
        for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
            if (strcmp(dot, table[i][0]) == 0) return table[i][1];
    return "application/octet-stream";
}
