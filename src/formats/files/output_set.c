/* All-or-nothing output of a run that writes several files or folders (see io.h,
 * sk_output_set): every output is reserved before the work starts, written under a
 * hidden staged name beside its final place, and renamed into place only when the whole
 * run succeeded; on failure, abort or a stopping signal the staged outputs are removed,
 * with the folders the set created. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/io_internal.h"
#include "shitsukan/io.h"

/* ENTRY_INSIDE: a file written into the staged copy of a folder reserved before it, and
   placed (or removed) with that folder */
typedef enum entry_kind { ENTRY_FILE, ENTRY_STREAM, ENTRY_FOLDER, ENTRY_INSIDE } entry_kind;

typedef struct entry {
    entry_kind kind;
    char *final;  /* where the output belongs (a link's target for files) */
    char *staged; /* where it is written until commit (the path given, for a stream) */
    int slot;     /* signal cleanup slot of `staged`, or -1 */
    bool placed;  /* commit has moved it into place */
    char **moved; /* folder: the files and folders commit moved into an existing final folder */
    int moved_count;
} entry;

struct sk_output_set {
    entry *entries;
    int count, capacity;
    char **created; /* folders the set created (parents of outputs), in creation order */
    int created_count, created_capacity;
    uint64_t salt;
};

sk_result sk_output_set_create(sk_output_set **out, sk_error *err)
{
    *out = calloc(1, sizeof **out);
    if (!*out) return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    (*out)->salt = sk_hash((uint64_t)getpid(), (uint64_t)(uintptr_t)*out,
                           (uint64_t)(sk_time_seconds() * 1e9), 1);
    return SK_OK;
}

static sk_result out_of_memory(sk_error *err)
{
    return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
}

static entry *add_entry(sk_output_set *set)
{
    if (set->count == set->capacity) {
        int capacity = set->capacity ? 2 * set->capacity : 8;
        entry *grown = realloc(set->entries, sizeof *grown * (size_t)capacity);
        if (!grown) return NULL;
        set->entries = grown;
        set->capacity = capacity;
    }
    entry *e = &set->entries[set->count++];
    memset(e, 0, sizeof *e);
    e->slot = -1;
    return e;
}

static bool already_reserved(const sk_output_set *set, const char *final)
{
    for (int i = 0; i < set->count; i++)
        if (strcmp(set->entries[i].final, final) == 0) return true;
    return false;
}

/* A fresh hidden name beside `final` that nothing uses yet; it keeps the final
   extension (".x.png.1a2b3c4d.part.png"), since writers pick the format by it. */
static char *staged_name(sk_output_set *set, const char *final)
{
    char suffix[32];
    const char *ext = sk__path_extension(final);
    snprintf(suffix, sizeof suffix, ".part%.16s", ext);
    for (int attempt = 0; attempt < 16; attempt++) {
        char *name = sk__sibling_name(final, suffix, sk_mix64(set->salt++));
        struct stat st;
        if (!name || lstat(name, &st) != 0) return name;
        free(name);
    }
    return NULL;
}

sk_result sk_output_check(const char *path, sk_error *err)
{
    char *final;
    sk__output_kind kind;
    sk_result r = sk__output_resolve(path, &final, &kind, err);
    if (r != SK_OK) return r;
    if (kind == SK__OUTPUT_FILE) r = sk__output_folder_exists(final, err);
    free(final);
    return r;
}

/* The reserved folder that `final` (a file path) names a file directly inside of, or NULL. */
static const entry *folder_holding(const sk_output_set *set, const char *final)
{
    const char *slash = strrchr(final, '/');
    if (!slash) return NULL;
    size_t dir_len = (size_t)(slash - final);
    for (int i = 0; i < set->count; i++) {
        const entry *e = &set->entries[i];
        if (e->kind == ENTRY_FOLDER && strlen(e->final) == dir_len &&
            strncmp(e->final, final, dir_len) == 0)
            return e;
    }
    return NULL;
}

sk_result sk_output_set_file(sk_output_set *set, const char *path, const char **staged,
                             sk_error *err)
{
    *staged = NULL;
    char *final;
    sk__output_kind kind;
    sk_result r = sk__output_resolve(path, &final, &kind, err);
    if (r != SK_OK) return r;
    /* a file inside a folder of the set goes into that folder's staged copy */
    const entry *holder = kind == SK__OUTPUT_FILE ? folder_holding(set, final) : NULL;
    /* a missing folder is found now, before the work */
    if (kind == SK__OUTPUT_FILE && !holder && (r = sk__output_folder_exists(final, err)) != SK_OK) {
        free(final);
        return r;
    }
    if (already_reserved(set, final)) {
        free(final);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: the same output is given twice", path);
    }
    /* a stream is written under the name given (a link keeps the extension writers read) */
    char *name = NULL;
    if (holder) {
        const char *base = strrchr(final, '/') + 1;
        size_t size = strlen(holder->staged) + 1 + strlen(base) + 1;
        if ((name = malloc(size)) != NULL) snprintf(name, size, "%s/%s", holder->staged, base);
    } else {
        name = kind == SK__OUTPUT_STREAM ? strdup(path) : staged_name(set, final);
    }
    entry *e = name ? add_entry(set) : NULL;
    if (!e) {
        free(name);
        free(final);
        return out_of_memory(err);
    }
    e->kind = holder ? ENTRY_INSIDE : kind == SK__OUTPUT_STREAM ? ENTRY_STREAM : ENTRY_FILE;
    e->final = final;
    e->staged = name;
    if (e->kind == ENTRY_FILE) e->slot = sk__cleanup_register(e->staged, false);
    *staged = e->staged;
    return SK_OK;
}

/* Creates the missing folders of `path` (not `path` itself when `self` is false),
   recording each for removal on abort. */
static sk_result make_folders(sk_output_set *set, const char *path, bool self, sk_error *err)
{
    char *buf = strdup(path);
    if (!buf) return out_of_memory(err);
    size_t len = strlen(buf);
    while (len > 1 && buf[len - 1] == '/') buf[--len] = '\0';
    sk_result r = SK_OK;
    for (char *p = buf + 1; r == SK_OK; p++) {
        char c = *p;
        if (c != '/' && c != '\0') continue;
        if (c == '\0' && !self) break;
        *p = '\0';
        struct stat st;
        if (stat(buf, &st) == 0) {
            if (!S_ISDIR(st.st_mode))
                r = sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: not a folder", buf);
        } else if (mkdir(buf, 0777) == 0) {
            if (set->created_count == set->created_capacity) {
                int capacity = set->created_capacity ? 2 * set->created_capacity : 8;
                char **grown = realloc(set->created, sizeof *grown * (size_t)capacity);
                if (grown) {
                    set->created = grown;
                    set->created_capacity = capacity;
                }
            }
            char *copy = set->created_count < set->created_capacity ? strdup(buf) : NULL;
            if (copy)
                set->created[set->created_count++] = copy;
            else
                r = out_of_memory(err);
        } else if (errno != EEXIST) {
            r = sk_fail(err, SK_ERROR_IO, "%s: cannot create folder (%s)", buf, strerror(errno));
        }
        *p = c;
        if (c == '\0') break;
    }
    free(buf);
    return r;
}

sk_result sk_output_set_folder(sk_output_set *set, const char *path, const char **staged,
                               sk_error *err)
{
    *staged = NULL;
    if (!path || !path[0]) return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "empty output folder");
    char *final = strdup(path);
    if (!final) return out_of_memory(err);
    size_t len = strlen(final);
    while (len > 1 && final[len - 1] == '/') final[--len] = '\0';
    struct stat st;
    if (stat(final, &st) == 0 && !S_ISDIR(st.st_mode)) {
        free(final);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: exists and is not a folder", path);
    }
    if (already_reserved(set, final)) {
        free(final);
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "%s: the same output is given twice", path);
    }
    sk_result r = make_folders(set, final, false, err);
    char *name = r == SK_OK ? staged_name(set, final) : NULL;
    if (r == SK_OK && !name) r = out_of_memory(err);
    if (r == SK_OK && mkdir(name, 0777) != 0)
        r = sk_fail(err, SK_ERROR_IO, "%s: cannot create folder (%s)", path, strerror(errno));
    entry *e = r == SK_OK ? add_entry(set) : NULL;
    if (r == SK_OK && !e) {
        rmdir(name);
        r = out_of_memory(err);
    }
    if (r != SK_OK) {
        free(name);
        free(final);
        return r;
    }
    e->kind = ENTRY_FOLDER;
    e->final = final;
    e->staged = name;
    e->slot = sk__cleanup_register(e->staged, true);
    *staged = e->staged;
    return SK_OK;
}

/* Removes a folder of this run's outputs with its files and subfolders. */
static void remove_folder(const char *path)
{
    DIR *dir = opendir(path);
    if (dir) {
        struct dirent *d;
        while ((d = readdir(dir)) != NULL) {
            if (strcmp(d->d_name, ".") == 0 || strcmp(d->d_name, "..") == 0) continue;
            char child[4096];
            snprintf(child, sizeof child, "%s/%s", path, d->d_name);
            struct stat st;
            if (lstat(child, &st) == 0 && S_ISDIR(st.st_mode))
                remove_folder(child);
            else
                unlink(child);
        }
        closedir(dir);
    }
    rmdir(path);
}

/* A file or folder this run moved into place: removed on undo. */
static void remove_moved(const char *path)
{
    struct stat st;
    if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode))
        remove_folder(path);
    else
        unlink(path);
}

static sk_result note_moved(entry *e, const char *to, sk_error *err)
{
    char **grown = realloc(e->moved, sizeof *grown * (size_t)(e->moved_count + 1));
    if (!grown) return out_of_memory(err);
    e->moved = grown;
    if (!(e->moved[e->moved_count] = strdup(to))) return out_of_memory(err);
    e->moved_count++;
    return SK_OK;
}

/* Moves what staged folder `from` holds into existing folder `to`: files (and folders `to`
   lacks) are renamed, a subfolder `to` already has is merged the same way. Everything
   moved is listed in e->moved for undoing. */
static sk_result merge_folder(entry *e, const char *from, const char *to, sk_error *err)
{
    DIR *dir = opendir(from);
    if (!dir) return sk_fail(err, SK_ERROR_IO, "%s: cannot read (%s)", from, strerror(errno));
    sk_result r = SK_OK;
    struct dirent *d;
    while (r == SK_OK && (d = readdir(dir)) != NULL) {
        if (strcmp(d->d_name, ".") == 0 || strcmp(d->d_name, "..") == 0) continue;
        char src[4096], dst[4096];
        snprintf(src, sizeof src, "%s/%s", from, d->d_name);
        snprintf(dst, sizeof dst, "%s/%s", to, d->d_name);
        struct stat s_st, d_st;
        if (lstat(src, &s_st) == 0 && S_ISDIR(s_st.st_mode) && stat(dst, &d_st) == 0 &&
            S_ISDIR(d_st.st_mode)) {
            r = merge_folder(e, src, dst, err);
            if (r == SK_OK) rmdir(src);
        } else if (rename(src, dst) != 0) {
            r = sk_fail(err, SK_ERROR_IO, "%s: cannot move into place (%s)", dst, strerror(errno));
        } else {
            r = note_moved(e, dst, err);
        }
    }
    closedir(dir);
    return r;
}

/* Moves the files of staged folder e into its final folder (or renames the folder when
   the final one does not exist yet). Moved names are listed in e->moved for undoing. */
static sk_result place_folder(sk_output_set *set, entry *e, sk_error *err)
{
    struct stat st;
    if (stat(e->final, &st) != 0) {
        if (rename(e->staged, e->final) != 0)
            return sk_fail(err, SK_ERROR_IO, "%s: cannot move into place (%s)", e->final,
                           strerror(errno));
        /* the folder itself is now this run's output */
        char **grown = realloc(set->created, sizeof *grown * (size_t)(set->created_count + 1));
        if (grown) {
            set->created = grown;
            set->created_capacity = set->created_count + 1;
            char *copy = strdup(e->final);
            if (copy) set->created[set->created_count++] = copy;
        }
        return SK_OK;
    }
    sk_result r = merge_folder(e, e->staged, e->final, err);
    if (r == SK_OK) rmdir(e->staged);
    return r;
}

static void destroy(sk_output_set *set)
{
    for (int i = 0; i < set->count; i++) {
        sk__cleanup_unregister(set->entries[i].slot);
        free(set->entries[i].final);
        free(set->entries[i].staged);
        for (int k = 0; k < set->entries[i].moved_count; k++) free(set->entries[i].moved[k]);
        free(set->entries[i].moved);
    }
    for (int i = 0; i < set->created_count; i++) free(set->created[i]);
    free(set->entries);
    free(set->created);
    free(set);
}

void sk_output_set_abort(sk_output_set *set)
{
    if (!set) return;
    for (int i = set->count - 1; i >= 0; i--) {
        entry *e = &set->entries[i];
        if (e->kind == ENTRY_FILE) {
            unlink(e->staged);
            if (e->placed) unlink(e->final);
        } else if (e->kind == ENTRY_FOLDER) {
            remove_folder(e->staged);
            for (int k = e->moved_count - 1; k >= 0; k--) remove_moved(e->moved[k]);
        }
    }
    /* folders the set created, deepest first (only if empty: never another's files) */
    for (int i = set->created_count - 1; i >= 0; i--) {
        const char *path = set->created[i];
        bool output_folder = false;
        for (int k = 0; k < set->count; k++)
            if (set->entries[k].kind == ENTRY_FOLDER && set->entries[k].placed &&
                strcmp(set->entries[k].final, path) == 0)
                output_folder = true;
        if (output_folder)
            remove_folder(path);
        else
            rmdir(path);
    }
    destroy(set);
}

sk_result sk_output_set_commit(sk_output_set *set, sk_error *err)
{
    sk_result r = SK_OK;
    /* files inside a folder of the set move with it: each must be there first */
    for (int i = 0; i < set->count && r == SK_OK; i++) {
        struct stat st;
        if (set->entries[i].kind == ENTRY_INSIDE && lstat(set->entries[i].staged, &st) != 0)
            r = sk_fail(err, SK_ERROR_IO, "%s: was not written", set->entries[i].final);
    }
    for (int i = 0; i < set->count && r == SK_OK; i++) {
        entry *e = &set->entries[i];
        if (e->kind == ENTRY_FILE) {
            struct stat st;
            if (lstat(e->staged, &st) != 0)
                r = sk_fail(err, SK_ERROR_IO, "%s: was not written", e->final);
            else if (rename(e->staged, e->final) != 0)
                r = sk_fail(err, SK_ERROR_IO, "%s: cannot move into place (%s)", e->final,
                            strerror(errno));
            else
                e->placed = true;
        } else if (e->kind == ENTRY_FOLDER) {
            r = place_folder(set, e, err);
            if (r == SK_OK) e->placed = true;
        }
    }
    if (r != SK_OK) {
        sk_output_set_abort(set);
        return r;
    }
    destroy(set);
    return SK_OK;
}
