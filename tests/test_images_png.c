/* Tests of the PNG writer's encoder: files decode with libpng to exactly the expected
 * codes (8/16-bit, 1-4 channels, sRGB and linear, with metadata), in one strip and in
 * many compressed in parallel; the same bytes on 1 and 2 threads; the sRGB table against
 * the curve at every code boundary; joining DEFLATE streams. */
#define _POSIX_C_SOURCE 200809L
#include "test_result.h"
#include "test_support.h"

#include <libdeflate.h>
#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "formats/images/deflate_join.h"
#include "base/image_internal.h"
#include "base/png_quantize.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* Under the sanitizers the images are smaller, still of several strips. */
static bool sanitized(void) { return getenv("SK_TEST_SANITIZED") != NULL; }

/* ------------------------------------------------------------------ references */

/* The 8-bit sRGB code by a search over the code boundaries in double (the definition):
 * code k starts at sRGB^-1((k - 1/2) / 255). */
static double g_boundary[256];

static unsigned srgb8_reference(float v)
{
    if (g_boundary[1] == 0.0)
        for (int k = 1; k < 256; k++) g_boundary[k] = sk__srgb_decode((k - 0.5) / 255.0);
    if (!(v > 0.0f)) return 0;
    unsigned lo = 0, hi = 255;
    while (lo < hi) {
        unsigned mid = (lo + hi + 1) / 2;
        if ((double)v >= g_boundary[mid])
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

static unsigned linear_reference(float v, unsigned max)
{
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return max;
    return (unsigned)floor((double)v * max + 0.5);
}

static unsigned code_reference(float v, int channel, int channels, int depth, sk_png_encoding enc)
{
    bool alpha = (channels == 2 && channel == 1) || (channels == 4 && channel == 3);
    unsigned max = depth == 16 ? 65535u : 255u;
    if (enc == SK_PNG_ENCODING_LINEAR || alpha) return linear_reference(v, max);
    if (depth == 8) return srgb8_reference(v);
    if (!(v > 0.0f)) return 0;
    return (unsigned)floor(sk__srgb_encode(v >= 1.0f ? 1.0 : v) * 65535.0 + 0.5);
}

/* Values that hit the interesting places: out of range, NaN, both ends, code boundaries. */
static float test_value(uint64_t seed, size_t i)
{
    static const float special[] = {-1.0f, 0.0f,       1.0f, 2.0f,    1e-7f,
                                    0.5f,  0.9999999f, NAN,  INFINITY};
    uint64_t h = sk_hash(seed, i, 0, 0);
    if (h % 17 == 0) return special[(h >> 8) % (sizeof special / sizeof special[0])];
    if (h % 5 == 0) { /* right at an sRGB boundary, or one float either side */
        float b = (float)sk__srgb_decode(((double)((h >> 8) % 255) + 0.5) / 255.0);
        int side = (int)((h >> 20) % 3) - 1;
        return side == 0 ? b : nextafterf(b, side < 0 ? 0.0f : 1.0f);
    }
    return (float)sk_u64_to_unit_d(h);
}

/* Decodes a PNG with libpng into its raw sample codes (no transformations). */
typedef struct decoded {
    int width, height, depth, color_type;
    unsigned *codes; /* width * height * channels */
    bool srgb, gama, chrm;
    int text_count;
    char keys[8][80], values[8][400];
} decoded;

static void decode_png(const char *path, decoded *d)
{
    memset(d, 0, sizeof *d);
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(png))) fail_msg("libpng could not decode %s", path);
    png_init_io(png, f);
    png_read_info(png, info);
    d->width = (int)png_get_image_width(png, info);
    d->height = (int)png_get_image_height(png, info);
    d->depth = png_get_bit_depth(png, info);
    d->color_type = png_get_color_type(png, info);
    int channels = png_get_channels(png, info);
    size_t row_bytes = png_get_rowbytes(png, info);
    unsigned char *row = malloc(row_bytes);
    d->codes = malloc(sizeof(unsigned) * (size_t)d->width * d->height * channels);
    for (int y = 0; y < d->height; y++) {
        png_read_row(png, row, NULL);
        for (size_t i = 0; i < (size_t)d->width * channels; i++)
            d->codes[(size_t)y * d->width * channels + i] =
                d->depth == 16 ? (unsigned)row[2 * i] << 8 | row[2 * i + 1] : row[i];
    }
    png_read_end(png, info);
    d->srgb = png_get_valid(png, info, PNG_INFO_sRGB) != 0;
    d->gama = png_get_valid(png, info, PNG_INFO_gAMA) != 0;
    d->chrm = png_get_valid(png, info, PNG_INFO_cHRM) != 0;
    png_textp texts;
    int n = 0;
    png_get_text(png, info, &texts, &n);
    for (int i = 0; i < n && i < 8; i++) {
        snprintf(d->keys[i], sizeof d->keys[i], "%s", texts[i].key);
        snprintf(d->values[i], sizeof d->values[i], "%s", texts[i].text);
    }
    d->text_count = n;
    png_destroy_read_struct(&png, &info, NULL);
    free(row);
    fclose(f);
}

/* ------------------------------------------------------------------ files */

static void check_layout(int width, int height, int channels, int depth, sk_png_encoding enc)
{
    char name[96];
    snprintf(name, sizeof name, "png/exact_%dx%d_%d_%d_%d.png", width, height, channels, depth,
             (int)enc);
    const char *path = sk_test_path(name);
    sk_image im;
    SK_ASSERT_OK(sk_image_create(&im, width, height, channels, &e_));
    size_t n = (size_t)width * height * channels;
    for (size_t i = 0; i < n; i++) im.data[i] = test_value(31u * channels + depth, i);
    sk_image_metadata meta = {0};
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "shitsukan:command", "test", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "Title", "\xe8\xb3\xaa\xe6\x84\x9f", &e_)); /* iTXt */
    sk_png_write_desc wd = {.bit_depth = depth, .encoding = enc, .metadata = &meta};
    SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
    decoded d;
    decode_png(path, &d);
    static const int types[5] = {0, PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                 PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
    assert_int_equal(d.width, width);
    assert_int_equal(d.height, height);
    assert_int_equal(d.depth, depth);
    assert_int_equal(d.color_type, types[channels]);
    for (size_t i = 0; i < n; i++) {
        unsigned want =
            code_reference(im.data[i], (int)(i % (size_t)channels), channels, depth, enc);
        if (d.codes[i] != want)
            fail_msg("%s sample %zu (%.9g): code %u, want %u", name, i, im.data[i], d.codes[i],
                     want);
    }
    bool srgb = enc == SK_PNG_ENCODING_SRGB;
    assert_int_equal(d.srgb, srgb);
    assert_int_equal(d.gama, srgb);
    assert_int_equal(d.chrm, srgb);
    assert_int_equal(d.text_count, 2);
    assert_string_equal(d.keys[0], "shitsukan:command");
    assert_string_equal(d.values[0], "test");
    assert_string_equal(d.keys[1], "Title");
    assert_string_equal(d.values[1], "\xe8\xb3\xaa\xe6\x84\x9f");
    free(d.codes);
    sk_image_free(&im);
}

static void test_png_decodes_exactly(void **state)
{
    (void)state;
    for (int channels = 1; channels <= 4; channels++)
        for (int depth = 8; depth <= 16; depth += 8) {
            check_layout(23, 17, channels, depth, SK_PNG_ENCODING_LINEAR);
            check_layout(23, 17, channels, depth, SK_PNG_ENCODING_SRGB);
            check_layout(1, 1, channels, depth, SK_PNG_ENCODING_SRGB);
        }
}

/* Images of several strips, compressed in parallel and joined into one stream, decode to
 * the same codes (every level, the strips' joins at odd bit positions). */
static void test_png_strips_decode_exactly(void **state)
{
    (void)state;
    bool small = sanitized();
    check_layout(700, small ? 600 : 1700, 3, 8,
                 SK_PNG_ENCODING_SRGB); /* 1.3 or 3.6 MB: 2 or 4 strips */
    check_layout(301, small ? 500 : 2000, 4, 16, SK_PNG_ENCODING_LINEAR); /* 1.2 or 9.6 MB */
    check_layout(16, 65536, 1, 8, SK_PNG_ENCODING_LINEAR); /* 17-byte rows: 2 strips */
    /* flat data compresses to a few bytes per strip; every level joins */
    const char *path = sk_test_path("png/flat.png");
    sk_image im;
    int side = small ? 640 : 1024;
    size_t n = (size_t)side * side * 3;
    SK_ASSERT_OK(sk_image_create(&im, side, side, 3, &e_));
    for (int level = 1; level <= 9; level++) {
        for (size_t i = 0; i < n; i++) im.data[i] = (float)(level & 1) * 0.5f;
        sk_png_write_desc wd = {.compression_level = level, .encoding = SK_PNG_ENCODING_LINEAR};
        SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
        decoded d;
        decode_png(path, &d);
        unsigned want = (unsigned)(level & 1) * 128u;
        for (size_t i = 0; i < n; i++)
            if (d.codes[i] != want) fail_msg("level %d sample %zu: %u", level, i, d.codes[i]);
        free(d.codes);
    }
    sk_image_free(&im);
}

/* Into memory: the bytes of the file. */
static void test_png_memory_equals_file(void **state)
{
    (void)state;
    sk_image im;
    SK_ASSERT_OK(sk_image_create(&im, 600, 900, 3, &e_)); /* two strips */
    for (size_t i = 0; i < (size_t)600 * 900 * 3; i++) im.data[i] = test_value(11, i);
    const char *path = sk_test_path("png/memory.png");
    SK_ASSERT_OK(sk_image_write_png(&im, path, NULL, &e_));
    uint8_t *bytes = NULL;
    size_t size = 0, file_size = 0;
    SK_ASSERT_OK(sk_image_write_png_memory(&im, NULL, &bytes, &size, &e_));
    char *file = NULL;
    SK_ASSERT_OK(sk_read_file(path, 0, &file, &file_size, &e_));
    assert_int_equal(size, file_size);
    assert_memory_equal(bytes, file, size);
    free(bytes);
    free(file);
    sk_png_write_desc bad = {.bit_depth = 12};
    bytes = (uint8_t *)path;
    assert_int_equal(sk_image_write_png_memory(&im, &bad, &bytes, &size, NULL),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_null(bytes);
    assert_int_equal(size, 0);
    sk_image_free(&im);
}

/* Rows given one at a time by a function: here the rows of an image, with the count of
 * calls (rows may be asked for more than once, from several threads). */
typedef struct rows_of_image {
    const sk_image *image;
    int calls;
} rows_of_image;

static void image_row(void *user, int y, float *row)
{
    rows_of_image *r = user;
    memcpy(row, sk_image_pixel(r->image, 0, y),
           sizeof(float) * (size_t)r->image->width * (size_t)r->image->channels);
#pragma omp atomic
    r->calls++;
}

/* The rows writer gives the bytes of the image writer, for one strip and for many, at 8
 * and 16 bits, sRGB and linear; a missing row function is refused. */
static void test_png_rows_equal_image(void **state)
{
    (void)state;
    const int shapes[3][3] = {{37, 11, 1}, {600, 900, 3}, {1000, 700, 4}}; /* one, 2 and 6 strips */
    const char *a = sk_test_path("png/rows_image.png"), *b = sk_test_path("png/rows_rows.png");
    for (int s = 0; s < 3; s++)
        for (int depth = 8; depth <= 16; depth += 8) {
            sk_image im;
            int w = shapes[s][0], h = shapes[s][1], c = shapes[s][2];
            SK_ASSERT_OK(sk_image_create(&im, w, h, c, &e_));
            for (size_t i = 0; i < (size_t)w * h * c; i++) im.data[i] = test_value(21 + s, i);
            sk_png_write_desc d = {.bit_depth = depth,
                                   .encoding =
                                       depth == 8 ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR};
            SK_ASSERT_OK(sk_image_write_png(&im, a, &d, &e_));
            rows_of_image user = {&im, 0};
            sk_image_rows rows = {
                .width = w, .height = h, .channels = c, .get_row = image_row, .user = &user};
            SK_ASSERT_OK(sk_image_write_png_rows(&rows, b, &d, &e_));
            assert_true(sk_test_same_file(a, b));
            assert_true(user.calls >= h);
            sk_image_free(&im);
        }
    sk_image_rows none = {.width = 4, .height = 4, .channels = 3};
    assert_int_equal(sk_image_write_png_rows(&none, b, NULL, NULL), SK_ERROR_INVALID_ARGUMENT);
    rows_of_image user = {NULL, 0};
    sk_image_rows wide = {
        .width = 70000, .height = 4, .channels = 3, .get_row = image_row, .user = &user};
    assert_int_not_equal(sk_image_write_png_rows(&wide, b, NULL, NULL), SK_OK);
    assert_int_equal(user.calls, 0);
}

static void test_png_same_bytes_any_threads(void **state)
{
    (void)state;
    sk_image im;
    int h = sanitized() ? 600 : 1300; /* 1.6 or 3.5 MB of rows */
    SK_ASSERT_OK(sk_image_create(&im, 900, h, 3, &e_));
    for (size_t i = 0; i < (size_t)900 * h * 3; i++) im.data[i] = test_value(5, i);
    const char *one = sk_test_path("png/threads1.png"), *two = sk_test_path("png/threads2.png");
    int threads = sk_threads_max();
    sk_threads_set(1);
    SK_ASSERT_OK(sk_image_write_png(&im, one, NULL, &e_));
    sk_threads_set(2);
    SK_ASSERT_OK(sk_image_write_png(&im, two, NULL, &e_));
    sk_threads_set(threads);
    assert_true(sk_test_same_file(one, two));
    sk_image_free(&im);
}

/* ------------------------------------------------------------------ the sRGB table */

static void test_srgb8_table_matches_curve(void **state)
{
    (void)state;
    sk__png_quantizer *q = malloc(sizeof *q);
    sk__png_quantizer_init(q, 3, 8, SK_PNG_ENCODING_SRGB);
    /* every code boundary and the 64 floats either side of it */
    for (int k = 0; k < 255; k++) {
        float b = (float)sk__srgb_decode((k + 0.5) / 255.0);
        float lo = b, hi = b;
        for (int s = 0; s < 64; s++) {
            lo = nextafterf(lo, 0.0f);
            hi = nextafterf(hi, 1.0f);
        }
        for (float v = lo; v <= hi; v = nextafterf(v, 2.0f))
            if (sk__png_srgb8_code(q, v) != srgb8_reference(v))
                fail_msg("boundary %d: %.9g gives %u, want %u", k, v, sk__png_srgb8_code(q, v),
                         srgb8_reference(v));
    }
    /* every bucket spans at most one boundary: its last float is at most one code on */
    for (uint32_t b = 0; b < SK__SRGB8_BUCKETS; b++) {
        uint32_t bits = SK__SRGB8_BUCKET_BASE + ((b + 1) << SK__SRGB8_BUCKET_SHIFT) - 1;
        float last;
        memcpy(&last, &bits, sizeof last);
        assert_true(srgb8_reference(last) <= q->bucket[b] + 1u);
    }
    /* a sweep over [0, 1] and the specials */
    for (uint32_t bits = 0; bits <= 0x3f800000u; bits += 9973) {
        float v;
        memcpy(&v, &bits, sizeof v);
        assert_int_equal(sk__png_srgb8_code(q, v), srgb8_reference(v));
    }
    const float special[] = {-0.0f, -1.0f,    NAN,      INFINITY, -INFINITY,
                             1.0f,  0x1p-20f, 0x1p-21f, 1e-30f};
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++)
        assert_int_equal(sk__png_srgb8_code(q, special[i]), srgb8_reference(special[i]));
    free(q);
}

/* ------------------------------------------------------------------ joining streams */

static void fill_pattern(uint8_t *p, size_t n, uint64_t seed, int kind)
{
    for (size_t i = 0; i < n; i++) {
        uint64_t h = sk_hash(seed, i / (kind == 2 ? 64 : 1), 0, 0);
        /* kind 3: byte k with probability 2^-(k+1), whose Huffman codes run to the
           longest DEFLATE allows (the walk's second-level tables) */
        uint8_t geometric = 0;
        while (geometric < 40 && (h >> geometric & 1)) geometric++;
        p[i] = kind == 0   ? (uint8_t)h
               : kind == 1 ? (uint8_t)(i % 251 + (h & 3))
               : kind == 2 ? (uint8_t)(h & 0x0f)
                           : geometric;
    }
}

/* Streams compressed apart, made continuable and concatenated decompress to the
 * concatenation; the Adler-32 of the whole follows from the parts'. */
static void test_deflate_join(void **state)
{
    (void)state;
    struct libdeflate_decompressor *dec = libdeflate_alloc_decompressor();
    const size_t sizes[4] = {1, 3000, 70000, 300000};
    for (int level = 1; level <= 12; level += 3)
        for (int kind = 0; kind < 4; kind++) {
            struct libdeflate_compressor *c = libdeflate_alloc_compressor(level);
            size_t total = 0;
            for (int k = 0; k < 4; k++) total += sizes[k];
            uint8_t *raw = malloc(total), *joined = malloc(2 * total + 1024), *back = malloc(total);
            size_t at = 0, out = 0;
            uint32_t adler = 1;
            for (int k = 0; k < 4; k++) {
                fill_pattern(raw + at, sizes[k], (uint64_t)(level * 10 + kind * 3 + k), kind);
                size_t m = libdeflate_deflate_compress(c, raw + at, sizes[k], joined + out,
                                                       2 * total + 1000 - out);
                assert_true(m > 0);
                if (k < 3) {
                    size_t h, e;
                    assert_true(sk__deflate_stream_end(joined + out, m, &h, &e));
                    assert_true((e + 7) / 8 == m);
                    assert_true(sk__deflate_make_continuable(joined + out, &m));
                }
                uint32_t a = libdeflate_adler32(1, raw + at, sizes[k]);
                adler = k == 0 ? a : sk__adler32_combine(adler, a, sizes[k]);
                out += m;
                at += sizes[k];
            }
            size_t got = 0;
            assert_int_equal(libdeflate_deflate_decompress(dec, joined, out, back, total, &got),
                             LIBDEFLATE_SUCCESS);
            assert_int_equal(got, total);
            assert_memory_equal(back, raw, total);
            assert_int_equal(adler, libdeflate_adler32(1, raw, total));
            free(raw);
            free(joined);
            free(back);
            libdeflate_free_compressor(c);
        }
    libdeflate_free_decompressor(dec);
}

/* Stored blocks join by construction; garbage and cut streams do not walk. */
static void test_deflate_store_and_bad_streams(void **state)
{
    (void)state;
    struct libdeflate_decompressor *dec = libdeflate_alloc_decompressor();
    size_t n = 150000;
    uint8_t *raw = malloc(n), *s = malloc(2 * sk__deflate_stored_bound(n)), *back = malloc(2 * n);
    fill_pattern(raw, n, 9, 0);
    size_t a = sk__deflate_store(raw, n, false, s);
    size_t b = sk__deflate_store(raw, n, true, s + a);
    assert_true(a <= sk__deflate_stored_bound(n));
    size_t got = 0;
    assert_int_equal(libdeflate_deflate_decompress(dec, s, a + b, back, 2 * n, &got),
                     LIBDEFLATE_SUCCESS);
    assert_int_equal(got, 2 * n);
    assert_memory_equal(back, raw, n);
    assert_memory_equal(back + n, raw, n);
    size_t h, e;
    assert_false(sk__deflate_stream_end(s, a, &h, &e)); /* no final block */
    assert_true(sk__deflate_stream_end(s + a, b, &h, &e));
    struct libdeflate_compressor *c = libdeflate_alloc_compressor(6);
    size_t m = libdeflate_deflate_compress(c, raw, n, s, 2 * n);
    for (size_t cut = 0; cut < m; cut += m / 50 + 1)
        assert_false(sk__deflate_stream_end(s, cut, &h, &e));
    fill_pattern(s, 4096, 3, 0);
    s[0] |= 6; /* block type 3 is reserved */
    assert_false(sk__deflate_stream_end(s, 4096, &h, &e));
    libdeflate_free_compressor(c);
    libdeflate_free_decompressor(dec);
    free(raw);
    free(s);
    free(back);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_png_decodes_exactly),
        cmocka_unit_test(test_png_strips_decode_exactly),
        cmocka_unit_test(test_png_memory_equals_file),
        cmocka_unit_test(test_png_rows_equal_image),
        cmocka_unit_test(test_png_same_bytes_any_threads),
        cmocka_unit_test(test_srgb8_table_matches_curve),
        cmocka_unit_test(test_deflate_join),
        cmocka_unit_test(test_deflate_store_and_bad_streams),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
