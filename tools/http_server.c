/* The studio's HTTP server loop: one listening socket and up to HTTP_MAX_CLIENTS
 * connections under poll(); each connection sends one request head, gets one whole
 * response (a file under the root, or an error) and is closed. Idle connections (e.g. a
 * browser's speculative ones) are dropped after HTTP_IDLE_SECONDS. */
#define _XOPEN_SOURCE 700
#include <arpa/inet.h>
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <netinet/in.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <time.h>
#include <unistd.h>

#include "http.h"
#include "shitsukan/io.h"

#define HTTP_MAX_CLIENTS 32
#define HTTP_IDLE_SECONDS 10

typedef struct client {
    int fd;
    size_t used;
    time_t since;
    char head[HTTP_MAX_HEAD];
} client;

static bool send_all(int fd, const void *data, size_t size)
{
    const char *p = data;
    while (size > 0) {
        ssize_t n = send(fd, p, size, MSG_NOSIGNAL);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        p += n;
        size -= (size_t)n;
    }
    return true;
}

/* Headers every response carries: cross-origin isolation (COOP/COEP, so the page may use
 * SharedArrayBuffer and precise timers), no sniffing, no caching of a changing build. */
static const char k_common_headers[] = "Cross-Origin-Opener-Policy: same-origin\r\n"
                                       "Cross-Origin-Embedder-Policy: require-corp\r\n"
                                       "Cross-Origin-Resource-Policy: same-origin\r\n"
                                       "X-Content-Type-Options: nosniff\r\n"
                                       "Cache-Control: no-cache\r\n"
                                       "Connection: close\r\n";

static int send_status(int fd, int status, const char *reason, bool head_only, const char *allow)
{
    char body[128], head[768];
    int blen = snprintf(body, sizeof body, "%d %s\n", status, reason);
    int n = snprintf(head, sizeof head,
                     "HTTP/1.1 %d %s\r\n%sContent-Type: text/plain; charset=utf-8\r\n"
                     "Content-Length: %d\r\n%s%s%s\r\n",
                     status, reason, k_common_headers, blen, allow ? "Allow: " : "",
                     allow ? allow : "", allow ? "\r\n" : "");
    send_all(fd, head, (size_t)n);
    if (!head_only) send_all(fd, body, (size_t)blen);
    return status;
}

/* The file for a request, or the error status to answer. */
static int open_file(const char *root_real, const char *path, int *fd_out, off_t *size, char *real,
                     size_t real_size)
{
    char rel[HTTP_MAX_PATH + 16], full[PATH_MAX];
    if (!http_relative_path(path, rel, sizeof rel)) return 404;
    if ((size_t)snprintf(full, sizeof full, "%s/%s", root_real, rel) >= sizeof full) return 404;
    char resolved[PATH_MAX];
    if (!realpath(full, resolved)) return 404;
    /* symbolic links inside the root must not lead out of it */
    size_t rl = strlen(root_real);
    if (strncmp(resolved, root_real, rl) != 0 || resolved[rl] != '/') return 404;
    int fd;
    long long file_size;
    if (sk_open_regular_fd(resolved, &fd, &file_size, NULL) != SK_OK) return 404;
    *fd_out = fd;
    *size = file_size;
    snprintf(real, real_size, "%s", resolved);
    return 200;
}

static int respond(int fd, const char *root_real, const char *data, size_t size)
{
    http_request req;
    http_parse_status st = http_parse_request(data, size, &req);
    switch (st) {
    case HTTP_PARSE_OK:
        break;
    case HTTP_PARSE_TOO_LARGE:
        return send_status(fd, 431, "Request Header Fields Too Large", false, NULL);
    case HTTP_PARSE_URI_TOO_LONG:
        return send_status(fd, 414, "URI Too Long", false, NULL);
    case HTTP_PARSE_VERSION:
        return send_status(fd, 505, "HTTP Version Not Supported", false, NULL);
    default:
        return send_status(fd, 400, "Bad Request", false, NULL);
    }
    bool head_only = strcmp(req.method, "HEAD") == 0;
    if (!head_only && strcmp(req.method, "GET") != 0)
        return send_status(fd, 405, "Method Not Allowed", false, "GET, HEAD");
    int file = -1;
    off_t length = 0;
    char real[PATH_MAX];
    int status = open_file(root_real, req.path, &file, &length, real, sizeof real);
    if (status != 200) return send_status(fd, status, "Not Found", head_only, NULL);
    char head[1024];
    int n = snprintf(head, sizeof head,
                     "HTTP/1.1 200 OK\r\n%sContent-Type: %s\r\nContent-Length: %lld\r\n\r\n",
                     k_common_headers, http_mime_type(real), (long long)length);
    bool ok = send_all(fd, head, (size_t)n);
    char buf[65536];
    while (ok && !head_only) {
        ssize_t got = read(file, buf, sizeof buf);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) break;
        ok = send_all(fd, buf, (size_t)got);
    }
    close(file);
    return 200;
}

static void log_request(FILE *log, const client *c, int status)
{
    if (!log) return;
    http_request req;
    if (http_parse_request(c->head, c->used, &req) == HTTP_PARSE_OK)
        fprintf(log, "%s %s %d\n", req.method, req.path, status);
    else
        fprintf(log, "(bad request) %d\n", status);
    fflush(log);
}

static int fail(char *error, size_t size, const char *what)
{
    snprintf(error, size, "%s: %s", what, strerror(errno));
    return -1;
}

int http_serve(const char *root, const char *host, int port, volatile sig_atomic_t *stop,
               void (*ready)(void *user, int port), void *user, FILE *log, char *error,
               size_t error_size)
{
    char root_real[PATH_MAX];
    if (!realpath(root, root_real)) return fail(error, error_size, root);
    struct stat st;
    if (stat(root_real, &st) != 0 || !S_ISDIR(st.st_mode)) {
        snprintf(error, error_size, "%s is not a folder", root);
        return -1;
    }
    struct sockaddr_in addr;
    memset(&addr, 0, sizeof addr);
    addr.sin_family = AF_INET;
    addr.sin_port = htons((uint16_t)port);
    if (inet_pton(AF_INET, host, &addr.sin_addr) != 1) {
        snprintf(error, error_size, "--host '%s' is not an IPv4 address", host);
        return -1;
    }
    int listener = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (listener < 0) return fail(error, error_size, "socket");
    int one = 1;
    setsockopt(listener, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (bind(listener, (struct sockaddr *)&addr, sizeof addr) != 0 || listen(listener, 64) != 0) {
        char what[96];
        snprintf(what, sizeof what, "%s:%d", host, port);
        fail(error, error_size, what);
        close(listener);
        return -1;
    }
    socklen_t alen = sizeof addr;
    getsockname(listener, (struct sockaddr *)&addr, &alen);
    if (ready) ready(user, ntohs(addr.sin_port));

    client *clients = calloc(HTTP_MAX_CLIENTS, sizeof *clients);
    if (!clients) {
        close(listener);
        snprintf(error, error_size, "out of memory");
        return -1;
    }
    for (int i = 0; i < HTTP_MAX_CLIENTS; i++) clients[i].fd = -1;
    struct pollfd fds[HTTP_MAX_CLIENTS + 1];
    while (!*stop) {
        int count = 0;
        fds[count++] = (struct pollfd){.fd = listener, .events = POLLIN};
        int map[HTTP_MAX_CLIENTS];
        for (int i = 0; i < HTTP_MAX_CLIENTS; i++)
            if (clients[i].fd >= 0) {
                map[count - 1] = i;
                fds[count++] = (struct pollfd){.fd = clients[i].fd, .events = POLLIN};
            }
        int ready_count = poll(fds, (nfds_t)count, 250);
        time_t now = time(NULL);
        if (ready_count < 0 && errno != EINTR) break;
        if (ready_count > 0 && (fds[0].revents & POLLIN)) {
            int fd = accept(listener, NULL, NULL);
            if (fd >= 0) {
                int slot = -1;
                for (int i = 0; i < HTTP_MAX_CLIENTS && slot < 0; i++)
                    if (clients[i].fd < 0) slot = i;
                if (slot < 0) {
                    send_status(fd, 503, "Service Unavailable", false, NULL);
                    close(fd);
                } else {
                    fcntl(fd, F_SETFD, FD_CLOEXEC);
                    /* a client that stops reading cannot hold the loop for long */
                    struct timeval limit = {HTTP_IDLE_SECONDS, 0};
                    setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &limit, sizeof limit);
                    clients[slot].fd = fd;
                    clients[slot].used = 0;
                    clients[slot].since = now;
                }
            }
        }
        for (int k = 1; ready_count > 0 && k < count; k++) {
            client *c = &clients[map[k - 1]];
            if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            ssize_t n = recv(c->fd, c->head + c->used, sizeof c->head - c->used, 0);
            bool done = n <= 0;
            if (n > 0) {
                c->used += (size_t)n;
                http_request req;
                http_parse_status s = http_parse_request(c->head, c->used, &req);
                if (s != HTTP_PARSE_INCOMPLETE || c->used == sizeof c->head) {
                    log_request(log, c, respond(c->fd, root_real, c->head, c->used));
                    done = true;
                }
            }
            if (done) {
                close(c->fd);
                c->fd = -1;
            }
        }
        for (int i = 0; i < HTTP_MAX_CLIENTS; i++)
            if (clients[i].fd >= 0 && now - clients[i].since > HTTP_IDLE_SECONDS) {
                close(clients[i].fd);
                clients[i].fd = -1;
            }
    }
    for (int i = 0; i < HTTP_MAX_CLIENTS; i++)
        if (clients[i].fd >= 0) close(clients[i].fd);
    free(clients);
    close(listener);
    return 0;
}
