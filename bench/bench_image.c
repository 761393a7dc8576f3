/* Benchmark of the image writers on real 2048 x 2048 maps (a Kawai Fig. 9 quarter-sawn
 * cut, an oak flat-sawn cut, a skin height and normal map): the PNG writer (libdeflate,
 * fixed Up filter, parallel strips) at its levels against libpng at zlib level 6 with its
 * adaptive filters on the same 8-bit codes, the float-to-sRGB quantiser against a per
 * sample search, and every EXR compression with its time and size. Writes into a
 * temporary folder under /tmp and removes it. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "base/image_internal.h"
#include "base/png_quantize.h"
#include "shitsukan/image.h"
#include "shitsukan/preset.h"
#include "shitsukan/skin.h"
#include "shitsukan/wood.h"

#define SIZE 2048

static void die(const char *what, const sk_error *err)
{
    fprintf(stderr, "bench_image: %s: %s\n", what, err ? err->message : "failed");
    exit(1);
}

static void load(const char *module, const char *name, const sk_schema *schema, void *desc)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s/%s.json", SK_BENCH_PRESET_DIR, module, name);
    sk_preset *p;
    sk_error err = {0};
    if (sk_preset_load_file(&p, path, &err) != SK_OK ||
        sk_preset_bind(p, schema, desc, &err) != SK_OK)
        die(path, &err);
    sk_preset_free(p);
}

/* A shaded wood cut of a preset's own view, one sample per pixel. */
static void wood_image(const char *preset, sk_image *out)
{
    sk_wood_desc desc;
    memset(&desc, 0, sizeof desc);
    load("wood", preset, &sk_wood_schema, &desc);
    sk_error err = {0};
    sk_wood *wood;
    if (sk_wood_create(&desc, &wood, &err) != SK_OK ||
        sk_image_create(out, SIZE, SIZE, 3, &err) != SK_OK)
        die(preset, &err);
    sk_wood_cut_desc cut = {0};
    sk_wood_view_cut(wood, &sk_wood_get_desc(wood)->view, &cut);
    cut.width = cut.height = SIZE;
    cut.samples = 1;
    cut.shaded = out->data;
    if (sk_wood_cut(wood, &cut, &err) != SK_OK) die(preset, &err);
    sk_wood_destroy(wood);
}

/* The back-of-hand skin's height in mm (height.exr of `skin maps`), scaled to [0, 1] (as
 * height.png) and the tangent-space normal (0.5 + 0.5 n). */
static void skin_images(sk_image *height_mm, sk_image *height, sk_image *normal)
{
    sk_skin_desc desc;
    memset(&desc, 0, sizeof desc);
    load("skin", "back-of-hand", &sk_skin_schema, &desc);
    sk_error err = {0};
    sk_skin *skin;
    if (sk_skin_create(&skin, &desc, &err) != SK_OK ||
        sk_image_create(height_mm, SIZE, SIZE, 1, &err) != SK_OK ||
        sk_image_create(height, SIZE, SIZE, 1, &err) != SK_OK ||
        sk_image_create(normal, SIZE, SIZE, 3, &err) != SK_OK)
        die("back-of-hand", &err);
    sk_skin_render_desc rd = {
        .width = SIZE, .height = SIZE, .height_mm = height_mm->data, .normal = normal->data};
    if (sk_skin_render(skin, &rd, &err) != SK_OK) die("back-of-hand", &err);
    float lo = INFINITY, hi = -INFINITY;
    size_t n = (size_t)SIZE * SIZE;
    for (size_t i = 0; i < n; i++) {
        lo = fminf(lo, height_mm->data[i]);
        hi = fmaxf(hi, height_mm->data[i]);
    }
    for (size_t i = 0; i < n; i++) height->data[i] = (height_mm->data[i] - lo) / (hi - lo);
    for (size_t i = 0; i < 3 * n; i++) normal->data[i] = 0.5f + 0.5f * normal->data[i];
    sk_skin_destroy(skin);
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

typedef struct timing {
    double seconds, cpu; /* wall and process CPU time of the best run */
    long bytes;
} timing;

/* CPU time of the whole process (all threads): on a shared machine wall time also counts
 * other processes, CPU time / threads is near what idle cores would take. */
static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static timing time_png(const sk_image *im, const char *path, const sk_png_write_desc *d, int runs)
{
    timing t = {1e30, 0, 0};
    for (int r = 0; r < runs; r++) {
        sk_error err = {0};
        double t0 = sk_time_seconds(), c0 = cpu_seconds();
        if (sk_image_write_png(im, path, d, &err) != SK_OK) die(path, &err);
        double dt = sk_time_seconds() - t0;
        if (dt < t.seconds) {
            t.seconds = dt;
            t.cpu = cpu_seconds() - c0;
        }
    }
    t.bytes = file_size(path);
    return t;
}

/* The codes the writer stores, for the libpng reference. */
static unsigned char *codes_of(const sk_image *im, int bit_depth, sk_png_encoding enc)
{
    sk__png_quantizer *q = malloc(sizeof *q);
    size_t row = (size_t)im->width * im->channels * (bit_depth / 8);
    unsigned char *codes = malloc(row * im->height);
    if (!q || !codes) die("codes", NULL);
    sk__png_quantizer_init(q, im->channels, bit_depth, enc);
    for (int y = 0; y < im->height; y++)
        sk__png_quantize_row(q, sk_image_pixel(im, 0, y), im->width, codes + row * y);
    free(q);
    return codes;
}

/* One libpng write of the codes at zlib level 6 with its adaptive row filters (what the
 * writer used before); false after a libpng error. */
static bool write_libpng(FILE *f, const sk_image *im, int bit_depth, const unsigned char *codes)
{
    static const int types[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                 PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    size_t row = (size_t)im->width * im->channels * (bit_depth / 8);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    if (!png || !info) return false;
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, f);
    png_set_compression_level(png, 6);
    png_set_IHDR(png, info, (png_uint_32)im->width, (png_uint_32)im->height, bit_depth,
                 types[im->channels], PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < im->height; y++) png_write_row(png, codes + row * y);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    return true;
}

static timing time_libpng(const sk_image *im, int bit_depth, sk_png_encoding enc, const char *path,
                          int runs)
{
    unsigned char *codes = codes_of(im, bit_depth, enc);
    timing t = {1e30, 0, 0};
    for (int r = 0; r < runs; r++) {
        double t0 = sk_time_seconds(), c0 = cpu_seconds();
        FILE *f = fopen(path, "wb");
        if (!f || !write_libpng(f, im, bit_depth, codes)) die("libpng", NULL);
        fclose(f);
        double dt = sk_time_seconds() - t0;
        if (dt < t.seconds) {
            t.seconds = dt;
            t.cpu = cpu_seconds() - c0;
        }
    }
    t.bytes = file_size(path);
    free(codes);
    return t;
}

/* 8-bit sRGB codes of every sample: the table against a search over the curve's code
 * boundaries in double (the quantiser before the table). */
static void time_quantiser(const sk_image *im)
{
    sk__png_quantizer *q = malloc(sizeof *q);
    size_t n = (size_t)im->width * im->height * im->channels;
    unsigned char *out = malloc(n);
    double boundary[255];
    for (int k = 0; k < 255; k++) boundary[k] = sk__srgb_decode((k + 0.5) / 255.0);
    if (!q || !out) die("quantiser", NULL);
    sk__png_quantizer_init(q, im->channels, 8, SK_PNG_ENCODING_SRGB);
    double table = 1e30, search = 1e30;
    size_t mismatches = 0;
    for (int r = 0; r < 3; r++) {
        double t0 = sk_time_seconds();
        for (int y = 0; y < im->height; y++)
            sk__png_quantize_row(q, sk_image_pixel(im, 0, y), im->width,
                                 out + (size_t)y * im->width * im->channels);
        double t1 = sk_time_seconds();
        mismatches = 0;
        for (size_t i = 0; i < n; i++) {
            float v = im->data[i];
            unsigned lo = 0, hi = 255;
            if (v > 0.0f)
                while (lo < hi) {
                    unsigned mid = (lo + hi + 1) / 2;
                    if ((double)v >= boundary[mid - 1])
                        lo = mid;
                    else
                        hi = mid - 1;
                }
            mismatches += lo != out[i];
        }
        double t2 = sk_time_seconds();
        table = fmin(table, t1 - t0);
        search = fmin(search, t2 - t1);
    }
    printf(
        "  float -> 8-bit sRGB, %zu samples, one thread: table %.1f ms, per-sample search %.1f ms "
        "(%.1fx), %zu codes differ\n",
        n, table * 1e3, search * 1e3, search / table, mismatches);
    free(q);
    free(out);
}

static void bench_png(const char *label, const sk_image *im, int bit_depth, sk_png_encoding enc,
                      const char *dir)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/bench.png", dir);
    int threads = sk_threads_max();
    printf("%s: %dx%d, %d channel(s), %d-bit %s PNG\n", label, im->width, im->height, im->channels,
           bit_depth, enc == SK_PNG_ENCODING_SRGB ? "sRGB" : "linear");
    timing ref = time_libpng(im, bit_depth, enc, path, 2);
    printf("  libpng, zlib level 6, adaptive filters (codes given): %7.1f ms (CPU %.1f ms) %9ld "
           "bytes\n",
           ref.seconds * 1e3, ref.cpu * 1e3, ref.bytes);
    for (int level = 0; level <= 9; level++) {
        if (level != 0 && level != 1 && level != 4 && level != 9) continue;
        sk_png_write_desc d = {.bit_depth = bit_depth, .encoding = enc, .compression_level = level};
        timing all = time_png(im, path, &d, 3);
        sk_threads_set(1);
        timing one = time_png(im, path, &d, 2);
        sk_threads_set(threads);
        char name[32];
        snprintf(name, sizeof name, level ? "level %d" : "default (6)", level);
        printf("  writer %-12s %d threads %6.1f ms (CPU %6.1f), 1 thread %6.1f ms (CPU %6.1f) %9ld "
               "bytes (%+.1f %% "
               "size; libpng's CPU / ours: %.1fx)\n",
               name, threads, all.seconds * 1e3, all.cpu * 1e3, one.seconds * 1e3, one.cpu * 1e3,
               all.bytes, 100.0 * (double)(all.bytes - ref.bytes) / (double)ref.bytes,
               ref.cpu / one.cpu);
    }
    unlink(path);
}

static void bench_exr(const char *label, const sk_image *im, const char *dir)
{
    char path[1200];
    snprintf(path, sizeof path, "%s/bench.exr", dir);
    printf("%s: %dx%d, %d channel(s), float EXR\n", label, im->width, im->height, im->channels);
    static const struct {
        const char *name;
        sk_exr_compression c;
        int level;
    } kinds[] = {{"NONE", SK_EXR_COMPRESSION_NONE, 0},      {"RLE", SK_EXR_COMPRESSION_RLE, 0},
                 {"ZIPS 1", SK_EXR_COMPRESSION_ZIPS, 1},    {"ZIPS 4", SK_EXR_COMPRESSION_ZIPS, 4},
                 {"ZIP 1", SK_EXR_COMPRESSION_ZIP, 1},      {"ZIP 4", SK_EXR_COMPRESSION_ZIP, 4},
                 {"ZIP 6", SK_EXR_COMPRESSION_ZIP, 6},      {"PIZ", SK_EXR_COMPRESSION_PIZ, 0},
                 {"default", SK_EXR_COMPRESSION_DEFAULT, 0}};
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        sk_exr_write_desc d = {.compression = kinds[k].c, .compression_level = kinds[k].level};
        double best = 1e30, cpu = 0;
        for (int r = 0; r < 2; r++) {
            sk_error err = {0};
            double t0 = sk_time_seconds(), c0 = cpu_seconds();
            if (sk_image_write_exr(im, path, &d, &err) != SK_OK) die(path, &err);
            double dt = sk_time_seconds() - t0;
            if (dt < best) {
                best = dt;
                cpu = cpu_seconds() - c0;
            }
        }
        long bytes = file_size(path);
        printf("  %-8s %7.1f ms (CPU %7.1f ms) %10ld bytes (%.2f of raw)\n", kinds[k].name,
               best * 1e3, cpu * 1e3, bytes,
               (double)bytes / ((double)im->width * im->height * im->channels * 4));
    }
    unlink(path);
}

int main(void)
{
    FILE *f = fopen("/proc/loadavg", "r");
    double load = -1;
    if (f && fscanf(f, "%lf", &load) != 1) load = -1;
    if (f) fclose(f);
    printf("machine load (1-minute average) %.2f on %d threads; best of 2-3 runs\n", load,
           sk_threads_max());
    char dir[] = "/tmp/sk_bench_image_XXXXXX";
    if (!mkdtemp(dir)) die("mkdtemp", NULL);
    sk_image fig9, oak, height_mm, height, normal;
    wood_image("fig9", &fig9);
    wood_image("oak", &oak);
    skin_images(&height_mm, &height, &normal);
    time_quantiser(&oak);
    bench_png("wood fig9 quarter-sawn cut", &fig9, 8, SK_PNG_ENCODING_SRGB, dir);
    bench_png("wood oak flat-sawn cut", &oak, 8, SK_PNG_ENCODING_SRGB, dir);
    bench_png("skin height map", &height, 16, SK_PNG_ENCODING_LINEAR, dir);
    bench_png("skin normal map", &normal, 8, SK_PNG_ENCODING_LINEAR, dir);
    bench_exr("wood fig9 quarter-sawn cut", &fig9, dir);
    bench_exr("skin height map (mm)", &height_mm, dir);
    rmdir(dir);
    sk_image_free(&fig9);
    sk_image_free(&oak);
    sk_image_free(&height_mm);
    sk_image_free(&height);
    sk_image_free(&normal);
    return 0;
}
