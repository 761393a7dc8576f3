/* The studio's small static-file HTTP/1.1 server (`shitsukan studio`): a strict request
 * parser, the mapping of a request path onto a file under the served root (no way out
 * of it), MIME types, and a poll loop that answers GET and HEAD with whole files and
 * the cross-origin isolation headers (COOP/COEP) threads in WebAssembly need. No Range,
 * no keep-alive: one request per connection. */
#ifndef SK_TOOLS_HTTP_H
#define SK_TOOLS_HTTP_H

#include <signal.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#define HTTP_MAX_HEAD 8192 /* request line + headers */
#define HTTP_MAX_PATH 1024 /* decoded path */

typedef enum http_parse_status {
    HTTP_PARSE_OK = 0,
    HTTP_PARSE_INCOMPLETE,   /* no blank line yet: read more */
    HTTP_PARSE_BAD,          /* 400 */
    HTTP_PARSE_TOO_LARGE,    /* head beyond HTTP_MAX_HEAD: 431 */
    HTTP_PARSE_URI_TOO_LONG, /* 414 */
    HTTP_PARSE_VERSION       /* not HTTP/1.0 or 1.1: 505 */
} http_parse_status;

typedef struct http_request {
    char method[16];
    char path[HTTP_MAX_PATH]; /* percent-decoded, without query or fragment */
    int minor_version;        /* HTTP/1.x */
    size_t head_bytes;        /* bytes of the request line and headers, blank line included */
} http_request;

/* Parses the head of a request from `data` (`size` bytes received so far). */
http_parse_status http_parse_request(const char *data, size_t size, http_request *out);

/* The file a decoded request path names, relative to the served root ("/" and paths
 * ending in "/" name their index.html): false for anything that could leave the root or
 * reach a hidden file (a "." or ".." segment, a segment starting with ".", a backslash,
 * a control character, an empty segment other than the trailing one). */
bool http_relative_path(const char *path, char *out, size_t size);

/* MIME type by extension (text types with charset=utf-8; .wasm application/wasm);
 * application/octet-stream for anything unknown. */
const char *http_mime_type(const char *path);

/* Serves `root` on host:port (port 0 = any free port) until *stop becomes non-zero.
 * `ready` (may be NULL) is called once listening, with the bound port. Requests are
 * logged to `log` (NULL = quiet). Returns 0, or -1 with a message in `error`. */
int http_serve(const char *root, const char *host, int port, volatile sig_atomic_t *stop,
               void (*ready)(void *user, int port), void *user, FILE *log, char *error,
               size_t error_size);

#endif /* SK_TOOLS_HTTP_H */
