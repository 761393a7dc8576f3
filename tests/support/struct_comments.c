/* Reading the members of a public header's struct and what their comments state (see
 * struct_comments.h). A small reader of the headers' own layout (clang-format's): one
 * declaration per line or wrapped, its comment after it, continued on following lines. */
#define _POSIX_C_SOURCE 200809L
#include "struct_comments.h"

#include <ctype.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "test_support.h"

/* The text of the header holding "typedef struct c_type {", from just after the brace. */
static char *find_struct(const char *c_type, char **start)
{
    char folder[1024], needle[160];
    snprintf(folder, sizeof folder, "%s/include/shitsukan", SK_TEST_SOURCE_DIR);
    snprintf(needle, sizeof needle, "typedef struct %s {", c_type);
    DIR *dir = opendir(folder);
    if (!dir) return NULL;
    struct dirent *e;
    char *found = NULL;
    while (!found && (e = readdir(dir)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 3 || strcmp(e->d_name + len - 2, ".h") != 0) continue;
        char path[2048];
        snprintf(path, sizeof path, "%s/%s", folder, e->d_name);
        char *text = sk_test_read_file(path);
        char *at = text ? strstr(text, needle) : NULL;
        if (at) {
            found = text;
            *start = at + strlen(needle);
        } else {
            free(text);
        }
    }
    closedir(dir);
    return found;
}

static void append(char *dst, size_t size, const char *src, size_t n)
{
    size_t used = strlen(dst);
    if (used + 1 >= size) return;
    if (n > size - used - 1) n = size - used - 1;
    memcpy(dst + used, src, n);
    dst[used + n] = '\0';
}

/* The names a declaration declares ("float from, to" -> from, to; arrays' brackets and
 * pointers dropped). */
static int declared_names(const char *decl, char names[][64], int max)
{
    char text[512];
    snprintf(text, sizeof text, "%s", decl);
    for (char *b = strchr(text, '['); b; b = strchr(text, '[')) { /* drop [N] */
        char *close = strchr(b, ']');
        if (!close) break;
        memmove(b, close + 1, strlen(close + 1) + 1);
    }
    int n = 0;
    char *part = text;
    while (part && n < max) {
        char *comma = strchr(part, ',');
        if (comma) *comma = '\0';
        /* the last identifier of the part */
        char *end = part + strlen(part);
        while (end > part && !(isalnum((unsigned char)end[-1]) || end[-1] == '_')) end--;
        char *begin = end;
        while (begin > part && (isalnum((unsigned char)begin[-1]) || begin[-1] == '_')) begin--;
        if (end > begin && end - begin < 64) {
            memcpy(names[n], begin, (size_t)(end - begin));
            names[n][end - begin] = '\0';
            n++;
        }
        part = comma ? comma + 1 : NULL;
    }
    return n;
}

int sk_test_struct_members(const char *c_type, sk_test_member *out, int max)
{
    char *start = NULL, *text = find_struct(c_type, &start);
    if (!text) return -1;
    int count = 0;
    char decl[512] = "";
    char *p = start;
    while (*p && count < max) {
        char *eol = strchr(p, '\n');
        size_t len = eol ? (size_t)(eol - p) : strlen(p);
        char line[1024];
        snprintf(line, sizeof line, "%.*s", (int)len, p);
        p = eol ? eol + 1 : p + len;
        char *l = line;
        while (isspace((unsigned char)*l)) l++;
        if (*l == '}') break;
        if (strncmp(l, "/*", 2) == 0) { /* a comment of its own: skip to its end */
            while (!strstr(l, "*/") && *p) {
                eol = strchr(p, '\n');
                len = eol ? (size_t)(eol - p) : strlen(p);
                snprintf(line, sizeof line, "%.*s", (int)len, p);
                l = line;
                p = eol ? eol + 1 : p + len;
            }
            continue;
        }
        char *semi = strchr(l, ';');
        if (!semi) { /* a declaration wrapped onto the next line */
            append(decl, sizeof decl, l, strlen(l));
            append(decl, sizeof decl, " ", 1);
            continue;
        }
        append(decl, sizeof decl, l, (size_t)(semi - l));
        char comment[1024] = "";
        char *c = strstr(semi, "/*");
        if (c) {
            c += 2;
            char *close = strstr(c, "*/");
            append(comment, sizeof comment, c, close ? (size_t)(close - c) : strlen(c));
            while (!close && *p) { /* the comment goes on */
                eol = strchr(p, '\n');
                len = eol ? (size_t)(eol - p) : strlen(p);
                snprintf(line, sizeof line, "%.*s", (int)len, p);
                p = eol ? eol + 1 : p + len;
                l = line;
                while (isspace((unsigned char)*l)) l++;
                close = strstr(l, "*/");
                append(comment, sizeof comment, " ", 1);
                append(comment, sizeof comment, l, close ? (size_t)(close - l) : strlen(l));
            }
        }
        char names[8][64];
        int n = declared_names(decl, names, 8);
        for (int i = 0; i < n && count < max; i++) {
            snprintf(out[count].name, sizeof out[count].name, "%s", names[i]);
            snprintf(out[count].comment, sizeof out[count].comment, "%s", comment);
            out[count].shared = n > 1;
            count++;
        }
        decl[0] = '\0';
    }
    free(text);
    return count;
}

/* A number at *p (after spaces): its value, and *p moved past it. */
static bool number_at(const char **p, double *out)
{
    const char *s = *p;
    while (*s == ' ') s++;
    if (!(isdigit((unsigned char)*s) || ((*s == '-' || *s == '+' || *s == '.') && s[1] &&
                                         (isdigit((unsigned char)s[1]) || s[1] == '.'))))
        return false;
    char *end;
    *out = strtod(s, &end);
    if (end == s) return false;
    *p = end;
    return true;
}

bool sk_test_comment_range(const char *comment, sk_test_range *out)
{
    bool found = false;
    for (const char *c = comment; *c; c++) {
        if (*c != '[' && *c != '(') continue;
        const char *before = c;
        while (before > comment && before[-1] == ' ') before--;
        if (before > comment && before[-1] == '=') continue; /* a value: "all 0 = (1, 1)" */
        const char *p = c + 1;
        double lo, hi;
        if (!number_at(&p, &lo)) continue;
        while (*p == ' ') p++;
        if (*p != ',') continue;
        p++;
        if (!number_at(&p, &hi)) continue;
        while (*p == ' ') p++;
        if (*p != ']' && *p != ')') continue;
        *out = (sk_test_range){lo, hi, *c == '(', *p == ')'};
        found = true;
    }
    return found;
}

/* After a number: the end, punctuation or a unit ("0.03 mm", "8 degrees"), not an
 * expression ("1 - specular", "5 x fat", "1.5 spacings"). */
static bool number_ends(const char *p)
{
    while (*p == ' ') p++;
    if (!*p || strchr(";,()", *p)) return true;
    static const char *const units[] = {"mm", "degrees", "deg", "pixels", "s", NULL};
    for (int i = 0; units[i]; i++) {
        size_t n = strlen(units[i]);
        if (strncmp(p, units[i], n) == 0 && !isalnum((unsigned char)p[n])) return true;
    }
    return false;
}

bool sk_test_comment_default(const char *comment, double *out)
{
    static const char *const lead[] = {"0 = default ", "0 = ", "default "};
    for (int k = 0; k < 3; k++) {
        const char *at = strstr(comment, lead[k]);
        if (!at) continue;
        /* "all 0 = ..." is an array's default */
        if (k < 2 && at >= comment + 4 && strncmp(at - 4, "all ", 4) == 0) continue;
        const char *p = at + strlen(lead[k]);
        if (number_at(&p, out) && number_ends(p)) return true;
    }
    return false;
}

bool sk_test_comment_defaults(const char *comment, double *out, int n)
{
    const char *at = strstr(comment, "all 0 = ");
    if (!at) return false;
    const char *p = strpbrk(at, "([");
    if (!p) return false;
    p++;
    for (int i = 0; i < n; i++) {
        if (!number_at(&p, &out[i])) return false;
        while (*p == ' ' || *p == ',') p++;
    }
    return true;
}

bool sk_test_comment_zero_means(const char *comment)
{
    return strstr(comment, "0 = ") || strstr(comment, "default 0");
}

bool sk_test_comment_key(const char *comment, char *key, int size)
{
    const char *at = strstr(comment, "key \"");
    if (!at) return false;
    at += 5;
    const char *end = strchr(at, '"');
    if (!end || end - at >= size) return false;
    memcpy(key, at, (size_t)(end - at));
    key[end - at] = '\0';
    return true;
}
