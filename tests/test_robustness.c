/* Regression tests of the library's input hardening: one strict JSON reader for every
 * JSON input, whole --set values, range endpoints at float precision, atomic files that
 * never replace a device, FIFO or symlink, output sets that are all-or-nothing, and the
 * readers' refusal of values beyond their types. Each test names the defect it guards. */
#define _POSIX_C_SOURCE 200809L
#include <fcntl.h>
#include <float.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cjson/cJSON.h>

#include "test_support.h"

#include "shitsukan/hand.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"
#include "shitsukan/mesh.h"
#include "shitsukan/noise_map.h"
#include "shitsukan/preset.h"
#include "shitsukan/render.h"
#include "shitsukan/skin.h"
#include "shitsukan/wood.h"

/* ------------------------------------------------------------ strict JSON */

static sk_result parse_constraints(const char *text, sk_error *err)
{
    sk_hand_skeleton skel;
    assert_int_equal(sk_hand_skeleton_init(&skel, NULL, NULL), SK_OK);
    sk_hand_constraints *c = malloc(sizeof *c);
    assert_non_null(c);
    sk_result r = sk_hand_constraints_parse(text, strlen(text), "c.json", &skel, c, err);
    free(c);
    return r;
}

static sk_result parse_animation(const char *text, sk_error *err)
{
    sk_hand_animation *a = malloc(sizeof *a);
    assert_non_null(a);
    sk_result r = sk_hand_animation_parse(text, strlen(text), "a.json", a, err);
    free(a);
    return r;
}

static sk_result parse_anatomy(const char *text, sk_error *err)
{
    sk_hand_anatomy anatomy;
    return sk_hand_anatomy_parse(text, strlen(text), "h.json", &anatomy, err);
}

/* Hand JSON files accepted trailing garbage and repeated keys, which presets refuse. */
static void test_hand_json_is_as_strict_as_presets(void **state)
{
    (void)state;
    sk_error err = {0};
    /* the same documents are valid without the defect */
    assert_int_equal(parse_constraints("{\"rows\": []}", &err), SK_OK);
    assert_int_equal(parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10}}]}", &err), SK_OK);
    assert_int_equal(parse_anatomy("{}", &err), SK_OK);

    assert_int_not_equal(parse_constraints("{\"rows\": []} junk", &err), SK_OK);
    assert_non_null(strstr(err.message, "unexpected text after the JSON value"));
    assert_int_not_equal(parse_constraints("{\"rows\": [], \"rows\": []}", &err), SK_OK);
    assert_non_null(strstr(err.message, "rows: key given twice"));
    assert_int_not_equal(parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10}}]}x", &err),
                         SK_OK);
    assert_non_null(strstr(err.message, "unexpected text after the JSON value"));
    assert_int_not_equal(
        parse_animation("{\"keys\": [{\"pin\": {\"L.MCP.flex\": 10, \"L.MCP.flex\": 20}}]}", &err),
        SK_OK);
    assert_non_null(strstr(err.message, "keys[0].pin.L.MCP.flex: key given twice"));
    assert_int_not_equal(parse_anatomy("{} {}", &err), SK_OK);
    assert_int_not_equal(parse_anatomy("{\"hand\": {}, \"hand\": {}}", &err), SK_OK);
    assert_non_null(strstr(err.message, "hand: key given twice"));
}

/* An integer literal beyond 2^53 silently lost digits (a seed of 2^53 + 1 became 2^53). */
static void test_json_refuses_inexact_integers(void **state)
{
    (void)state;
    sk_preset *p = NULL;
    sk_error err = {0};
    const char *exact =
        "{\"seed\": 9007199254740992, \"x\": 1.5e300, \"s\": \"12345678901234567890\"}";
    assert_int_equal(sk_preset_parse(&p, exact, strlen(exact), "p", &err), SK_OK);
    sk_preset_free(p);
    const char *inexact = "{\"seed\": 9007199254740993}";
    assert_int_equal(sk_preset_parse(&p, inexact, strlen(inexact), "p", &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "9007199254740993 is beyond 2^53"));
    assert_non_null(strstr(err.message, "p:1:10:"));
    const char *negative = "{\"x\": [-123456789012345678]}";
    assert_int_not_equal(sk_preset_parse(&p, negative, strlen(negative), "p", &err), SK_OK);
}

/* --set kept whatever valid prefix it found: cells=5junk ran as 5, seamless=truex as true,
 * cells=0x10 said "cells = 0 is out of range", seed=2^53+1 was accepted. */
static void test_set_parses_the_whole_value(void **state)
{
    (void)state;
    static const struct {
        const char *assignment, *message;
    } cases[] = {
        {"cells=5junk", "cells: expected a number, got the string \"5junk\""},
        {"seamless=truex", "seamless: expected true or false, got the string \"truex\""},
        {"cells=0x10", "cells: expected a number, got the string \"0x10\""},
        {"cells=5 6", "cells: expected a number, got the string \"5 6\""},
        {"seed=9007199254740993", "integer 9007199254740993 is beyond 2^53"},
        {"cells=nan", "cells is not a finite number"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        sk_preset *p = NULL;
        sk_error err = {0};
        assert_int_equal(sk_preset_create(&p, &err), SK_OK);
        sk_result r = sk_preset_set(p, cases[i].assignment, &err);
        if (r == SK_OK) {
            sk_noise_map_desc d;
            memset(&d, 0, sizeof d);
            r = sk_preset_bind(p, &sk_noise_map_schema, &d, &err);
        }
        sk_preset_free(p);
        if (r == SK_OK || !strstr(err.message, cases[i].message))
            fail_msg("%s: got %d '%s', expected '%s'", cases[i].assignment, r, err.message,
                     cases[i].message);
    }
    /* whole values still parse as before */
    sk_preset *p = NULL;
    sk_error err = {0};
    assert_int_equal(sk_preset_create(&p, &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "cells=5", &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "seamless=true", &err), SK_OK);
    assert_int_equal(sk_preset_set(p, "seed=9007199254740992", &err), SK_OK);
    sk_noise_map_desc d;
    memset(&d, 0, sizeof d);
    assert_int_equal(sk_preset_bind(p, &sk_noise_map_schema, &d, &err), SK_OK);
    assert_int_equal(d.cells, 5);
    assert_true(d.seamless);
    assert_true(d.seed == 9007199254740992ull);
    sk_preset_free(p);
}

/* "hand calibrate" on samples of 1e308 wrote rows of null and exited 0. */
static void test_calibration_refuses_overflow(void **state)
{
    (void)state;
    double x[4] = {1e200, 2e200, 3e200, 5e200}, y[4] = {1, 2, 3, 1e200};
    const double *columns[SK_HAND_DOF_COUNT] = {0};
    int dx = sk_hand_dof_find("L.MCP.flex"), dy = sk_hand_dof_find("R.MCP.flex");
    columns[dx] = x;
    columns[dy] = y;
    int pairs[1][2] = {{dx, dy}};
    sk_hand_fit fit;
    sk_error err = {0};
    assert_int_equal(
        sk_hand_calibrate(columns, 4, (const int(*)[2])pairs, 1, SK_HAND_WEIGHT_THESIS, &fit, &err),
        SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "L.MCP.flex:R.MCP.flex"));
    /* and the samples file refuses such values, naming the range */
    const char *csv = "L.MCP.flex,R.MCP.flex\n1e308,1\n2,3\n4,5\n";
    sk_hand_samples samples;
    assert_int_equal(sk_hand_samples_parse(csv, strlen(csv), "s.csv", &samples, &err),
                     SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "[-1e6, 1e6]"));
}

/* ------------------------------------------------------------ range endpoints */

/* Documented endpoints were refused once stored as float: "view.width_mm = 0.01 is out of
 * range [0.01, 100000]", fibre.cell_mm = 0.005, rings.latewood_fraction = 0.01 / 0.99,
 * rings.transition = 0.99. */
static void test_documented_endpoints_are_accepted(void **state)
{
    (void)state;
    assert_true(sk_in_range_f((double)0.99f, 0.01, 0.99));
    assert_true(sk_in_range_f((double)0.01f, 0.01, 0.99));
    assert_true(sk_in_range_f((double)1e-6f, 1e-6, 1e9));
    assert_false(sk_in_range_f(0.98, 0.99, 1.0));
    assert_false(sk_in_range_f((double)nextafterf(0.99f, 1.0f), 0.01, 0.99));
    assert_false(sk_in_range_f(NAN, 0, 1));
    assert_false(sk_in_range_f(1e300, 0, 1e299));
    assert_true(sk_in_range_f(1e300, 0, 1e301));

    static const char *const sets[] = {
        "view.width_mm=0.01",           "fibre.cell_mm=0.005",   "rings.latewood_fraction=0.01",
        "rings.latewood_fraction=0.99", "rings.transition=0.99",
    };
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        sk_preset *p = NULL;
        sk_error err = {0};
        assert_int_equal(sk_preset_create(&p, &err), SK_OK);
        assert_int_equal(sk_preset_set(p, sets[i], &err), SK_OK);
        if (i == 4) assert_int_equal(sk_preset_set(p, "rings.latewood_fraction=0.01", &err), SK_OK);
        sk_wood_desc d;
        memset(&d, 0, sizeof d);
        assert_int_equal(sk_preset_bind(p, &sk_wood_schema, &d, &err), SK_OK);
        sk_preset_free(p);
        sk_wood *wood = NULL;
        if (sk_wood_create(&d, &wood, &err) != SK_OK) fail_msg("%s: %s", sets[i], err.message);
        sk_wood_destroy(wood);
    }
    /* render unit_mm = 1e-6, the documented minimum */
    sk_render_scene_desc *scene = calloc(1, sizeof *scene);
    assert_non_null(scene);
    scene->unit_mm = 1e-6f;
    sk_error err = {0};
    if (sk_render_scene_desc_validate(scene, &err) != SK_OK) fail_msg("unit_mm: %s", err.message);
    scene->unit_mm = 0.9e-6f;
    assert_int_equal(sk_render_scene_desc_validate(scene, &err), SK_ERROR_INVALID_ARGUMENT);
    free(scene);
}

/* Every float and double key of the skin and wood schemas (their nested objects too, as
 * the schema describes them) at its documented minimum and maximum: binding and validating
 * never says that very value is out of range (a key may still be refused with another, as
 * a pair of keys that must be ordered). */
typedef sk_result (*validate_fn)(const void *desc, sk_error *err);
static sk_result validate_skin(const void *d, sk_error *err)
{
    return sk_skin_desc_validate(d, err);
}
static sk_result validate_wood(const void *d, sk_error *err)
{
    return sk_wood_desc_validate(d, err);
}

static int sweep_endpoints(const sk_schema *schema, const cJSON *fields, const char *prefix,
                           validate_fn validate, size_t desc_size, int *checked)
{
    int failures = 0;
    const cJSON *f;
    cJSON_ArrayForEach(f, fields)
    {
        const cJSON *key = cJSON_GetObjectItemCaseSensitive(f, "key");
        const cJSON *type = cJSON_GetObjectItemCaseSensitive(f, "type");
        if (!cJSON_IsString(key) || !cJSON_IsString(type)) continue;
        char path[256];
        snprintf(path, sizeof path, "%s%s%s", prefix, prefix[0] ? "." : "", key->valuestring);
        if (strcmp(type->valuestring, "object") == 0) {
            failures += sweep_endpoints(schema, cJSON_GetObjectItemCaseSensitive(f, "fields"), path,
                                        validate, desc_size, checked);
            continue;
        }
        if (strcmp(type->valuestring, "float") != 0 && strcmp(type->valuestring, "double") != 0)
            continue;
        const cJSON *ends[2] = {cJSON_GetObjectItemCaseSensitive(f, "min"),
                                cJSON_GetObjectItemCaseSensitive(f, "max")};
        for (int e = 0; e < 2; e++) {
            if (!cJSON_IsNumber(ends[e])) continue;
            char set[320];
            snprintf(set, sizeof set, "%s=%.17g", path, ends[e]->valuedouble);
            sk_preset *p = NULL;
            sk_error err = {0};
            assert_int_equal(sk_preset_create(&p, &err), SK_OK);
            void *desc = calloc(1, desc_size);
            assert_non_null(desc);
            sk_result r = sk_preset_set(p, set, &err);
            if (r == SK_OK) r = sk_preset_bind(p, schema, desc, &err);
            if (r == SK_OK) r = validate(desc, &err);
            char refused[300];
            snprintf(refused, sizeof refused, "%s = ", path);
            if (r != SK_OK && strstr(err.message, refused) && strstr(err.message, "out of range")) {
                print_error("%s: %s\n", set, err.message);
                failures++;
            }
            (*checked)++;
            sk_preset_free(p);
            free(desc);
        }
    }
    return failures;
}

static void test_every_schema_endpoint_is_accepted(void **state)
{
    (void)state;
    const struct {
        const sk_schema *schema;
        validate_fn validate;
        size_t size;
    } schemas[] = {{&sk_skin_schema, validate_skin, sizeof(sk_skin_desc)},
                   {&sk_wood_schema, validate_wood, sizeof(sk_wood_desc)}};
    int failures = 0, checked = 0;
    for (size_t i = 0; i < sizeof schemas / sizeof schemas[0]; i++) {
        char *text = sk_schema_describe_json(schemas[i].schema);
        assert_non_null(text);
        cJSON *root = cJSON_Parse(text);
        free(text);
        assert_non_null(root);
        failures +=
            sweep_endpoints(schemas[i].schema, cJSON_GetObjectItemCaseSensitive(root, "fields"), "",
                            schemas[i].validate, schemas[i].size, &checked);
        cJSON_Delete(root);
    }
    assert_true(checked > 40);
    assert_int_equal(failures, 0);
}

/* ------------------------------------------------------------ atomic files */

/* A fresh empty folder for one test. */
static const char *fresh_folder(const char *name)
{
    const char *path = sk_test_path(name);
    char command[2048];
    snprintf(command, sizeof command, "rm -rf '%s' && mkdir -p '%s'", path, path);
    assert_int_equal(system(command), 0);
    return path;
}

static sk_result write_text(const char *path, const char *text, sk_error *err)
{
    sk_atomic_file f;
    sk_result r = sk_atomic_file_open(&f, path, err);
    if (r != SK_OK) return r;
    fputs(text, f.fp);
    return sk_atomic_file_commit(&f, err);
}

static void read_text(const char *path, char *out, size_t size)
{
    FILE *fp = fopen(path, "rb");
    assert_non_null(fp);
    size_t n = fread(out, 1, size - 1, fp);
    out[n] = '\0';
    fclose(fp);
}

/* -o onto a symlink replaced the link with a regular file. */
static void test_atomic_file_writes_through_symlinks(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/link");
    char target_dir[1024], target[1024], link[1024], chain[1024], buf[64];
    snprintf(target_dir, sizeof target_dir, "%s/real", dir);
    assert_int_equal(mkdir(target_dir, 0777), 0);
    snprintf(target, sizeof target, "%s/real/file.txt", dir);
    snprintf(link, sizeof link, "%s/link.txt", dir);
    snprintf(chain, sizeof chain, "%s/chain.txt", dir);
    assert_int_equal(symlink("real/file.txt", link), 0); /* relative, dangling at first */
    assert_int_equal(symlink("link.txt", chain), 0);
    sk_error err = {0};
    assert_int_equal(write_text(link, "one", &err), SK_OK);
    struct stat st;
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    read_text(target, buf, sizeof buf);
    assert_string_equal(buf, "one");
    assert_int_equal(write_text(chain, "two", &err), SK_OK);
    assert_int_equal(lstat(chain, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
    read_text(target, buf, sizeof buf);
    assert_string_equal(buf, "two");
    /* the temporary file went beside the target, and is gone */
    assert_int_equal(sk_test_count_files_containing(target_dir, ".tmp"), 0);
    assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
    /* a loop is refused */
    char loop_a[1024], loop_b[1024];
    snprintf(loop_a, sizeof loop_a, "%s/loop_a", dir);
    snprintf(loop_b, sizeof loop_b, "%s/loop_b", dir);
    assert_int_equal(symlink("loop_b", loop_a), 0);
    assert_int_equal(symlink("loop_a", loop_b), 0);
    assert_int_equal(write_text(loop_a, "x", &err), SK_ERROR_INVALID_ARGUMENT);
}

/* -o /dev/null turned /dev/null into a PNG (as root); a FIFO was replaced likewise. */
static void test_atomic_file_writes_devices_and_fifos_in_place(void **state)
{
    (void)state;
    sk_error err = {0};
    struct stat st;
    assert_int_equal(write_text("/dev/null", "into the void", &err), SK_OK);
    assert_int_equal(stat("/dev/null", &st), 0);
    assert_true(S_ISCHR(st.st_mode));
    /* a full device reports its reason */
    if (stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode)) {
        sk_atomic_file f;
        assert_int_equal(sk_atomic_file_open(&f, "/dev/full", &err), SK_OK);
        for (int i = 0; i < 1000; i++) fputs("0123456789abcdef0123456789abcdef", f.fp);
        assert_int_equal(sk_atomic_file_commit(&f, &err), SK_ERROR_IO);
        assert_non_null(strstr(err.message, "No space left on device"));
        /* the EXR writer hung (a lock taken twice) on a write error; now it reports it */
        const char *links = fresh_folder("robust/full");
        char full[1024];
        snprintf(full, sizeof full, "%s/full.exr", links);
        assert_int_equal(symlink("/dev/full", full), 0);
        sk_image image = {0};
        assert_int_equal(sk_image_create(&image, 4, 4, 3, &err), SK_OK);
        assert_int_equal(sk_image_write_exr(&image, full, NULL, &err), SK_ERROR_IO);
        assert_non_null(strstr(err.message, "No space left on device"));
        sk_image_free(&image);
    }
    const char *dir = fresh_folder("robust/fifo");
    char fifo[1024];
    snprintf(fifo, sizeof fifo, "%s/pipe", dir);
    assert_int_equal(mkfifo(fifo, 0666), 0);
    /* a reader drains the FIFO (open blocks until both ends are there) */
    pid_t child = fork();
    assert_true(child >= 0);
    if (child == 0) {
        char buf[256];
        int fd = open(fifo, O_RDONLY);
        ssize_t n = fd >= 0 ? read(fd, buf, sizeof buf) : -1;
        _exit(n == 5 && memcmp(buf, "piped", 5) == 0 ? 0 : 1);
    }
    assert_int_equal(write_text(fifo, "piped", &err), SK_OK);
    int status;
    assert_int_equal(waitpid(child, &status, 0), child);
    assert_true(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    assert_int_equal(lstat(fifo, &st), 0);
    assert_true(S_ISFIFO(st.st_mode));
    assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
    /* a folder is refused, not replaced */
    assert_int_equal(write_text(dir, "x", &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "names a folder"));
    assert_int_equal(stat(dir, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
}

/* An output name of about 241 characters failed: the temporary name was longer than
 * NAME_MAX. */
static void test_atomic_file_takes_the_longest_names(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/long");
    char name[256], path[2048];
    for (int len = 240; len <= 255; len += 5) {
        memset(name, 'n', (size_t)len);
        memcpy(name + len - 4, ".txt", 4);
        name[len] = '\0';
        snprintf(path, sizeof path, "%s/%s", dir, name);
        sk_error err = {0};
        if (write_text(path, "long", &err) != SK_OK)
            fail_msg("%d characters: %s", len, err.message);
        assert_true(sk_test_file_exists(path));
        /* the same name in an output set */
        sk_output_set *set = NULL;
        const char *staged;
        assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
        assert_int_equal(sk_output_set_file(set, path, &staged, &err), SK_OK);
        assert_int_equal(write_text(staged, "again", &err), SK_OK);
        assert_int_equal(sk_output_set_commit(set, &err), SK_OK);
    }
    assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
}

/* SIGTERM or SIGINT while writing left ".NAME.XXXXXXXX.tmp" behind. */
static void test_signal_removes_unfinished_outputs(void **state)
{
    (void)state;
    static const int signals[] = {SIGTERM, SIGINT};
    for (int k = 0; k < 2; k++) {
        const char *dir = fresh_folder(k == 0 ? "robust/signal-term" : "robust/signal-int");
        int ready[2];
        assert_int_equal(pipe(ready), 0);
        pid_t child = fork();
        assert_true(child >= 0);
        if (child == 0) {
            char path[1024], folder[1024];
            snprintf(path, sizeof path, "%s/file.txt", dir);
            snprintf(folder, sizeof folder, "%s/frames", dir);
            sk_atomic_file f;
            sk_output_set *set = NULL;
            const char *staged_file, *staged_folder;
            if (sk_atomic_file_open(&f, path, NULL) != SK_OK) _exit(3);
            if (sk_output_set_create(&set, NULL) != SK_OK ||
                sk_output_set_file(set, path, &staged_file, NULL) != SK_OK ||
                sk_output_set_folder(set, folder, &staged_folder, NULL) != SK_OK)
                _exit(4);
            char inside[1024];
            snprintf(inside, sizeof inside, "%s/frame_0001.txt", staged_folder);
            if (write_text(staged_file, "staged", NULL) != SK_OK ||
                write_text(inside, "frame", NULL) != SK_OK)
                _exit(5);
            fputs("partial", f.fp);
            fflush(f.fp);
            if (write(ready[1], "r", 1) != 1) _exit(6);
            for (;;) pause();
        }
        close(ready[1]);
        char c;
        assert_int_equal(read(ready[0], &c, 1), 1);
        close(ready[0]);
        /* the unfinished outputs are there ... */
        assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 1);
        assert_int_equal(sk_test_count_files_containing(dir, ".part"), 2);
        /* ... the process ends by the signal, and they are gone */
        sk_test_kill_and_reap(child, signals[k]);
        assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
        assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
        assert_int_equal(sk_test_count_files_containing(dir, "file.txt"), 0);
        assert_int_equal(sk_test_count_files_containing(dir, "frames"), 0);
    }
}

/* ------------------------------------------------------------ output sets */

/* Multi-file outputs were not all-or-nothing: when a later file failed, the earlier ones
 * stayed. */
static void test_output_set_is_all_or_nothing(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/set");
    char a[1024], b[1024], frames[1024], nested[1024], buf[64];
    snprintf(a, sizeof a, "%s/a.png", dir);
    snprintf(b, sizeof b, "%s/b.txt", dir);
    snprintf(frames, sizeof frames, "%s/frames", dir);
    snprintf(nested, sizeof nested, "%s/new/deeper/frames", dir);
    sk_error err = {0};

    /* commit: everything appears, under the final names, with the staged extension kept */
    sk_output_set *set = NULL;
    const char *sa, *sb, *sf, *sn;
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, a, &sa, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, b, &sb, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, frames, &sf, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, nested, &sn, &err), SK_OK);
    assert_non_null(strstr(sa, ".png"));
    assert_string_equal(sa + strlen(sa) - 4, ".png");
    /* the same output twice is refused */
    const char *again;
    assert_int_equal(sk_output_set_file(set, a, &again, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(write_text(sa, "A", &err), SK_OK);
    assert_int_equal(write_text(sb, "B", &err), SK_OK);
    char frame[1024];
    snprintf(frame, sizeof frame, "%s/frame_1.txt", sf);
    assert_int_equal(write_text(frame, "F", &err), SK_OK);
    snprintf(frame, sizeof frame, "%s/frame_1.txt", sn);
    assert_int_equal(write_text(frame, "N", &err), SK_OK);
    assert_false(sk_test_file_exists(a));
    assert_int_equal(sk_output_set_commit(set, &err), SK_OK);
    read_text(a, buf, sizeof buf);
    assert_string_equal(buf, "A");
    snprintf(frame, sizeof frame, "%s/frame_1.txt", frames);
    read_text(frame, buf, sizeof buf);
    assert_string_equal(buf, "F");
    snprintf(frame, sizeof frame, "%s/frame_1.txt", nested);
    read_text(frame, buf, sizeof buf);
    assert_string_equal(buf, "N");
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);

    /* abort after a partial run: nothing new stays, earlier outputs are untouched, the
       folders the set created are gone */
    char c[1024], more[1024];
    snprintf(c, sizeof c, "%s/c.txt", dir);
    snprintf(more, sizeof more, "%s/made/by/set", dir);
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, a, &sa, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, c, &sb, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, frames, &sf, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, more, &sn, &err), SK_OK);
    assert_int_equal(write_text(sa, "A2", &err), SK_OK);
    snprintf(frame, sizeof frame, "%s/frame_2.txt", sf);
    assert_int_equal(write_text(frame, "F2", &err), SK_OK);
    sk_output_set_abort(set);
    read_text(a, buf, sizeof buf);
    assert_string_equal(buf, "A");
    assert_false(sk_test_file_exists(c));
    snprintf(frame, sizeof frame, "%s/frame_2.txt", frames);
    assert_false(sk_test_file_exists(frame));
    snprintf(more, sizeof more, "%s/made", dir);
    assert_false(sk_test_file_exists(more));
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);

    /* a folder with subfolders (as tissue run's frames/): committed into the existing
       folder, the subfolders merged; aborted, nothing of it stays */
    char sub[1024];
    for (int round = 0; round < 3; round++) {
        assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
        assert_int_equal(sk_output_set_folder(set, frames, &sf, &err), SK_OK);
        snprintf(sub, sizeof sub, "%s/sub", sf);
        assert_int_equal(sk_make_dirs(sub, &err), SK_OK);
        snprintf(frame, sizeof frame, "%s/sub/f%d.txt", sf, round);
        assert_int_equal(write_text(frame, "S", &err), SK_OK);
        if (round < 2) {
            assert_int_equal(sk_output_set_commit(set, &err), SK_OK);
        } else {
            sk_output_set_abort(set);
        }
        snprintf(frame, sizeof frame, "%s/sub/f%d.txt", frames, round);
        assert_int_equal(sk_test_file_exists(frame), round < 2);
    }
    snprintf(frame, sizeof frame, "%s/sub/f0.txt", frames);
    assert_true(sk_test_file_exists(frame));
    /* a commit that fails after merging a subfolder takes the merged files back out */
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, frames, &sf, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, c, &sb, &err), SK_OK);
    snprintf(sub, sizeof sub, "%s/sub", sf);
    assert_int_equal(sk_make_dirs(sub, &err), SK_OK);
    snprintf(frame, sizeof frame, "%s/sub/f9.txt", sf);
    assert_int_equal(write_text(frame, "S", &err), SK_OK);
    assert_int_equal(sk_output_set_commit(set, &err), SK_ERROR_IO); /* c was not written */
    snprintf(frame, sizeof frame, "%s/sub/f9.txt", frames);
    assert_false(sk_test_file_exists(frame));
    snprintf(frame, sizeof frame, "%s/sub/f1.txt", frames);
    assert_true(sk_test_file_exists(frame));
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);

    /* a reserved file that was never written fails the commit, which removes the rest */
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, c, &sb, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, b, &sa, &err), SK_OK);
    assert_int_equal(write_text(sb, "C", &err), SK_OK);
    assert_int_equal(sk_output_set_commit(set, &err), SK_ERROR_IO);
    assert_non_null(strstr(err.message, "was not written"));
    assert_false(sk_test_file_exists(c));
    read_text(b, buf, sizeof buf);
    assert_string_equal(buf, "B");

    /* bad outputs are refused when reserved, before any work */
    char missing[1024];
    snprintf(missing, sizeof missing, "%s/no-such-folder/x.png", dir);
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, missing, &sa, &err), SK_ERROR_IO);
    assert_int_equal(sk_output_set_file(set, frames, &sa, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_output_set_folder(set, a, &sa, &err), SK_ERROR_INVALID_ARGUMENT);
    sk_output_set_abort(set);
}

/* ------------------------------------------------------------ readers */

/* `wood cut -o DIR/shaded.png --maps DIR` was refused ("cannot create file") when DIR did
 * not exist yet: the picture's folder is the maps folder, which the set makes only at the
 * end. A file directly inside a folder reserved before it goes into its staged copy. */
static void test_output_set_file_inside_its_folder(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/inside");
    char maps[1024], shaded[1024], path[1024], buf[64];
    snprintf(maps, sizeof maps, "%s/oak", dir);
    snprintf(shaded, sizeof shaded, "%s/oak/shaded.png", dir);
    sk_error err = {0};
    for (int existing = 0; existing < 2; existing++) {
        /* the folder new, then already there: the file lands inside it either way */
        sk_output_set *set = NULL;
        const char *sf, *ss;
        assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
        assert_int_equal(sk_output_set_folder(set, maps, &sf, &err), SK_OK);
        assert_int_equal(sk_output_set_file(set, shaded, &ss, &err), SK_OK);
        assert_int_equal(strncmp(ss, sf, strlen(sf)), 0);
        assert_int_equal(write_text(ss, existing ? "S2" : "S", &err), SK_OK);
        snprintf(path, sizeof path, "%s/albedo.png", sf);
        assert_int_equal(write_text(path, "A", &err), SK_OK);
        /* nothing in place before the commit (the earlier file, the second time) */
        if (existing)
            read_text(shaded, buf, sizeof buf), assert_string_equal(buf, "S");
        else
            assert_false(sk_test_file_exists(shaded));
        assert_int_equal(sk_output_set_commit(set, &err), SK_OK);
        read_text(shaded, buf, sizeof buf);
        assert_string_equal(buf, existing ? "S2" : "S");
        snprintf(path, sizeof path, "%s/albedo.png", maps);
        assert_true(sk_test_file_exists(path));
        assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
    }
    /* not written: commit fails and leaves nothing new */
    char other[1024], other_file[1024];
    snprintf(other, sizeof other, "%s/maple", dir);
    snprintf(other_file, sizeof other_file, "%s/maple/shaded.png", dir);
    sk_output_set *set = NULL;
    const char *sf, *ss;
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, other, &sf, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, other_file, &ss, &err), SK_OK);
    snprintf(path, sizeof path, "%s/albedo.png", sf);
    assert_int_equal(write_text(path, "A", &err), SK_OK);
    assert_int_equal(sk_output_set_commit(set, &err), SK_ERROR_IO);
    assert_non_null(strstr(err.message, "was not written"));
    assert_false(sk_test_file_exists(other));
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
    /* aborted: the folder and the file inside are gone */
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_folder(set, other, &sf, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, other_file, &ss, &err), SK_OK);
    assert_int_equal(write_text(ss, "S", &err), SK_OK);
    sk_output_set_abort(set);
    assert_false(sk_test_file_exists(other));
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
    /* a file reserved before its folder still needs the folder to exist */
    char late[1024], late_file[1024];
    snprintf(late, sizeof late, "%s/late", dir);
    snprintf(late_file, sizeof late_file, "%s/late/shaded.png", dir);
    assert_int_equal(sk_output_set_create(&set, &err), SK_OK);
    assert_int_equal(sk_output_set_file(set, late_file, &ss, &err), SK_ERROR_IO);
    sk_output_set_abort(set);
}

/* PLY "property double" values above FLT_MAX loaded as inf (ASCII and binary). */
static void test_ply_refuses_doubles_beyond_float(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/ply");
    char path[1024];
    snprintf(path, sizeof path, "%s/big.ply", dir);
    const char *ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                        "property double y\nproperty double z\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n"
                        "0 0 0\n1 0 1e39\n0 1 0\n3 0 1 2\n";
    sk_test_write_file(path, ascii, strlen(ascii));
    sk_mesh mesh;
    sk_error err = {0};
    assert_int_equal(sk_mesh_read(&mesh, path, NULL, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "out of float range"));
    /* the same in binary */
    const char *header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\n"
                         "property double x\nproperty double y\nproperty double z\n"
                         "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    unsigned char data[1024];
    size_t n = strlen(header);
    memcpy(data, header, n);
    double v[9] = {0, 0, 0, 1, 0, -1e300, 0, 1, 0};
    memcpy(data + n, v, sizeof v); /* the test machines are little-endian */
    n += sizeof v;
    data[n++] = 3;
    int idx[3] = {0, 1, 2};
    memcpy(data + n, idx, sizeof idx);
    n += sizeof idx;
    sk_test_write_file(path, data, n);
    assert_int_equal(sk_mesh_read(&mesh, path, NULL, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "out of float range"));
    /* FLT_MAX itself is a float */
    v[5] = (double)FLT_MAX;
    memcpy(data + strlen(header), v, sizeof v);
    sk_test_write_file(path, data, n);
    assert_int_equal(sk_mesh_read(&mesh, path, NULL, &err), SK_OK);
    sk_mesh_free(&mesh);
}

/* A folder given as an input file exited 1 (runtime) instead of 2 (bad input). */
static void test_folder_as_input_is_bad_input(void **state)
{
    (void)state;
    const char *dir = fresh_folder("robust/input.png");
    sk_error err = {0};
    char *data;
    size_t size;
    assert_int_equal(sk_read_file(dir, 0, &data, &size, &err), SK_ERROR_INVALID_ARGUMENT);
    sk_image image = {0};
    assert_int_equal(sk_image_read_png(&image, dir, NULL, NULL, NULL, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_image_read_exr(&image, dir, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
    sk_mesh mesh;
    assert_int_equal(sk_mesh_read_ply(&mesh, dir, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_int_equal(sk_mesh_read_obj(&mesh, dir, NULL, &err), SK_ERROR_INVALID_ARGUMENT);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hand_json_is_as_strict_as_presets),
        cmocka_unit_test(test_json_refuses_inexact_integers),
        cmocka_unit_test(test_set_parses_the_whole_value),
        cmocka_unit_test(test_calibration_refuses_overflow),
        cmocka_unit_test(test_documented_endpoints_are_accepted),
        cmocka_unit_test(test_every_schema_endpoint_is_accepted),
        cmocka_unit_test(test_atomic_file_writes_through_symlinks),
        cmocka_unit_test(test_atomic_file_writes_devices_and_fifos_in_place),
        cmocka_unit_test(test_atomic_file_takes_the_longest_names),
        cmocka_unit_test(test_signal_removes_unfinished_outputs),
        cmocka_unit_test(test_output_set_is_all_or_nothing),
        cmocka_unit_test(test_output_set_file_inside_its_folder),
        cmocka_unit_test(test_ply_refuses_doubles_beyond_float),
        cmocka_unit_test(test_folder_as_input_is_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
