/* Tests of the image module: allocation caps, metadata, the sRGB curve, PNG and EXR round
 * trips, foreign and malformed files, and atomic writing. */
#define _POSIX_C_SOURCE 200809L
#include "test_result.h"
#include "test_support.h"

#include <OpenEXR/openexr.h>
#include <math.h>
#include <png.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/image_internal.h"
#include "shitsukan/image.h"
#include "shitsukan/io.h"

/* ------------------------------------------------------------------ helpers */

static void fill_random(sk_image *im, uint64_t seed, float lo, float hi)
{
    size_t n = (size_t)im->width * im->height * im->channels;
    for (size_t i = 0; i < n; i++)
        im->data[i] = (float)sk_rand_uniform(seed, i, 0, 0) * (hi - lo) + lo;
}

static long file_size(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static unsigned char *slurp(const char *path, size_t *size)
{
    char *data = NULL;
    assert_int_equal(sk_read_file(path, 0, &data, size, NULL), SK_OK);
    return (unsigned char *)data;
}

static bool contains_bytes(const unsigned char *data, size_t size, const char *needle)
{
    size_t n = strlen(needle);
    for (size_t i = 0; i + n <= size; i++)
        if (memcmp(data + i, needle, n) == 0) return true;
    return false;
}

static void folder_of(const char *path, char *out, size_t cap)
{
    snprintf(out, cap, "%s", path);
    char *slash = strrchr(out, '/');
    if (slash) *slash = '\0';
}

/* ------------------------------------------------------------------ core */

static void test_image_create_caps(void **state)
{
    (void)state;
    sk_image im;
    sk_error err = {0};
    sk_test_expect_failure(sk_image_create(&im, SK_IMAGE_MAX_DIMENSION + 1, 1, 1, &err), &err,
                           SK_ERROR_LIMIT, "65536");
    assert_null(im.data);
    /* 65536^2 x 4 floats is 64 GiB: over the byte cap although each side is allowed. */
    sk_test_expect_failure(sk_image_create(&im, 65536, 65536, 4, &err), &err, SK_ERROR_LIMIT,
                           "bytes");
    assert_null(im.data);
    sk_test_expect_failure(sk_image_create(&im, 0, 4, 1, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           NULL);
    sk_test_expect_failure(sk_image_create(&im, 4, 4, 5, &err), &err, SK_ERROR_INVALID_ARGUMENT,
                           "channels");
    SK_ASSERT_OK(sk_image_create(&im, 3, 2, 4, &e_));
    for (int i = 0; i < 3 * 2 * 4; i++) assert_true(im.data[i] == 0.0f);
    assert_ptr_equal(sk_image_pixel(&im, 2, 1), im.data + (1 * 3 + 2) * 4);
    sk_image_free(&im);
    assert_null(im.data);
}

static void test_metadata_set_get(void **state)
{
    (void)state;
    sk_image_metadata meta = {0};
    sk_error err = {0};
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "a", "1", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "b", "2", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "a", "3", &e_));
    assert_int_equal(meta.count, 2);
    assert_string_equal(sk_image_metadata_get(&meta, "a"), "3");
    assert_null(sk_image_metadata_get(&meta, "c"));
    char long_key[100];
    memset(long_key, 'k', sizeof long_key - 1);
    long_key[sizeof long_key - 1] = '\0';
    sk_test_expect_failure(sk_image_metadata_set(&meta, long_key, "v", &err), &err, SK_ERROR_LIMIT,
                           "key");
    sk_test_expect_failure(sk_image_metadata_set(&meta, "", "v", &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, NULL);
    for (int i = meta.count; i < SK_IMAGE_MAX_METADATA; i++) {
        char key[16];
        snprintf(key, sizeof key, "k%d", i);
        SK_ASSERT_OK(sk_image_metadata_set(&meta, key, "x", &e_));
    }
    sk_test_expect_failure(sk_image_metadata_set(&meta, "one_more", "v", &err), &err,
                           SK_ERROR_LIMIT, "full");
    /* Replacing an existing key still works when full. */
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "b", "4", &e_));
    assert_string_equal(sk_image_metadata_get(&meta, "b"), "4");
}

static void test_srgb_curve(void **state)
{
    (void)state;
    /* 1.055 * 0.5^(1/2.4) - 0.055 = 0.735356983... */
    assert_float_equal(sk_srgb_from_linear(0.5f), 0.7353570f, 1e-6);
    assert_float_equal(sk_srgb_from_linear(0.0f), 0.0f, 0.0);
    assert_float_equal(sk_srgb_from_linear(1.0f), 1.0f, 1e-6);
    /* Linear segment: 12.92 * x. */
    assert_float_equal(sk_srgb_from_linear(0.001f), 0.01292f, 1e-7);
    assert_float_equal(sk_linear_from_srgb(0.04f), 0.04f / 12.92f, 1e-8);
    /* The two segments meet at 0.0031308 / 0.04045 (continuity to the curve's 1e-7). */
    assert_float_equal(sk_srgb_from_linear(0.0031308f), 0.04045f, 2e-6);
    for (int i = 0; i <= 1000; i++) {
        float x = (float)i / 1000.0f;
        assert_float_equal(sk_linear_from_srgb(sk_srgb_from_linear(x)), x, 2e-6);
    }
    assert_true(isnan(sk_srgb_from_linear(NAN)));
}

/* ------------------------------------------------------------------ PNG */

static void png_roundtrip(int channels, int bit_depth, sk_png_encoding encoding)
{
    char name[64];
    snprintf(name, sizeof name, "image/rt_%d_%d_%d.png", channels, bit_depth, (int)encoding);
    const char *path = sk_test_path(name);
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 23, 17, channels, &e_));
    fill_random(&im, 7u + (uint64_t)channels, 0.0f, 1.0f);
    sk_png_write_desc wd = {0};
    wd.bit_depth = bit_depth;
    wd.encoding = encoding;
    SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
    sk_png_read_desc rd = {0};
    rd.encoding = encoding;
    int depth = 0;
    SK_ASSERT_OK(sk_image_read_png(&back, path, &rd, NULL, &depth, &e_));
    assert_int_equal(depth, bit_depth);
    assert_int_equal(back.width, 23);
    assert_int_equal(back.height, 17);
    assert_int_equal(back.channels, channels);
    double max_code = bit_depth == 16 ? 65535.0 : 255.0;
    size_t n = (size_t)23 * 17 * channels;
    for (size_t i = 0; i < n; i++) {
        int c = (int)(i % (size_t)channels);
        bool alpha = (channels == 2 && c == 1) || (channels == 4 && c == 3);
        double a = im.data[i], b = back.data[i];
        /* Within half a code where the codes live: sRGB space for colour, linear for alpha. */
        if (encoding == SK_PNG_ENCODING_SRGB && !alpha) {
            a = sk_srgb_from_linear((float)a);
            b = sk_srgb_from_linear((float)b);
        }
        if (fabs(a - b) > 0.5 / max_code + 1e-6)
            fail_msg("channels %d depth %d sample %zu: %.7f vs %.7f", channels, bit_depth, i, a, b);
    }
    sk_image_free(&im);
    sk_image_free(&back);
}

static void test_png_roundtrip_all_layouts(void **state)
{
    (void)state;
    for (int channels = 1; channels <= 4; channels++)
        for (int depth = 8; depth <= 16; depth += 8) {
            png_roundtrip(channels, depth, SK_PNG_ENCODING_LINEAR);
            png_roundtrip(channels, depth, SK_PNG_ENCODING_SRGB);
        }
}

/* The zlib level changes the file size, never the pixels; out-of-range levels are refused. */
static void test_png_compression_level(void **state)
{
    (void)state;
    sk_image img = {0};
    assert_int_equal(sk_image_create(&img, 256, 128, 3, NULL), SK_OK);
    for (int i = 0; i < 256 * 128 * 3; i++) img.data[i] = (float)((i * 7) % 256) / 255.0f;
    const char *fast = sk_test_path("image/level1.png"), *small = sk_test_path("image/level9.png");
    sk_png_write_desc d1 = {.compression_level = 1}, d9 = {.compression_level = 9};
    assert_int_equal(sk_image_write_png(&img, fast, &d1, NULL), SK_OK);
    assert_int_equal(sk_image_write_png(&img, small, &d9, NULL), SK_OK);
    char *a, *b;
    size_t sa, sb;
    assert_int_equal(sk_read_file(fast, 0, &a, &sa, NULL), SK_OK);
    assert_int_equal(sk_read_file(small, 0, &b, &sb, NULL), SK_OK);
    assert_true(sb < sa);
    free(a);
    free(b);
    sk_image ra = {0}, rb = {0};
    assert_int_equal(sk_image_read_png(&ra, fast, NULL, NULL, NULL, NULL), SK_OK);
    assert_int_equal(sk_image_read_png(&rb, small, NULL, NULL, NULL, NULL), SK_OK);
    assert_memory_equal(ra.data, rb.data, sizeof(float) * 256 * 128 * 3);
    sk_error err = {0};
    sk_png_write_desc bad = {.compression_level = 10};
    assert_int_equal(sk_image_write_png(&img, fast, &bad, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "compression_level = 10 is out of range [1, 9]"));
    sk_image_free(&ra);
    sk_image_free(&rb);
    sk_image_free(&img);
}

static void test_png_16bit_gradient_exact(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/gradient16.png");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 256, 256, 1, &e_));
    for (int i = 0; i < 65536; i++) im.data[i] = (float)i / 65535.0f;
    sk_png_write_desc wd = {.bit_depth = 16, .encoding = SK_PNG_ENCODING_LINEAR};
    SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
    sk_png_read_desc rd = {.encoding = SK_PNG_ENCODING_LINEAR};
    SK_ASSERT_OK(sk_image_read_png(&back, path, &rd, NULL, NULL, &e_));
    for (int i = 0; i < 65536; i++)
        if (back.data[i] != im.data[i])
            fail_msg("code %d came back as %.9g", i, back.data[i] * 65535.0);
    sk_image_free(&im);
    sk_image_free(&back);
}

/* A 16-bit sRGB image large enough for the reader's lookup table decodes every code
 * exactly as the curve does. */
static void test_png_16bit_srgb_table(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/gradient16_srgb.png");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 512, 256, 1, &e_));
    for (int i = 0; i < 512 * 256; i++)
        im.data[i] = (float)sk__srgb_decode((double)(i % 65536) / 65535.0);
    sk_png_write_desc wd = {.bit_depth = 16};
    SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
    SK_ASSERT_OK(sk_image_read_png(&back, path, NULL, NULL, NULL, &e_));
    for (int i = 0; i < 512 * 256; i++)
        if (back.data[i] != im.data[i])
            fail_msg("code %d: %.9g, want %.9g", i % 65536, back.data[i], im.data[i]);
    sk_image_free(&im);
    sk_image_free(&back);
}

static void test_png_srgb_encoding_known_code(void **state)
{
    (void)state;
    const char *srgb_path = sk_test_path("image/half_grey_srgb.png");
    const char *lin_path = sk_test_path("image/half_grey_linear.png");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 1, 1, 2, &e_));
    im.data[0] = 0.5f; /* grey */
    im.data[1] = 0.5f; /* alpha stays linear */
    SK_ASSERT_OK(sk_image_write_png(&im, srgb_path, NULL, &e_));
    sk_png_write_desc lin = {.encoding = SK_PNG_ENCODING_LINEAR};
    SK_ASSERT_OK(sk_image_write_png(&im, lin_path, &lin, &e_));

    sk_png_read_desc raw = {.encoding = SK_PNG_ENCODING_LINEAR};
    SK_ASSERT_OK(sk_image_read_png(&back, srgb_path, &raw, NULL, NULL, &e_));
    assert_float_equal(back.data[0] * 255.0f, 188.0f, 1e-3); /* 255 * 0.73536 = 187.5 */
    assert_float_equal(back.data[1] * 255.0f, 128.0f, 1e-3); /* 127.5 rounds up */
    sk_image_free(&back);
    SK_ASSERT_OK(sk_image_read_png(&back, lin_path, &raw, NULL, NULL, &e_));
    assert_float_equal(back.data[0] * 255.0f, 128.0f, 1e-3);
    sk_image_free(&back);
    /* Default read decodes sRGB: 188 -> 0.5029. */
    SK_ASSERT_OK(sk_image_read_png(&back, srgb_path, NULL, NULL, NULL, &e_));
    assert_float_equal(back.data[0], sk_linear_from_srgb(188.0f / 255.0f), 1e-6);
    sk_image_free(&back);

    size_t size;
    unsigned char *bytes = slurp(srgb_path, &size);
    assert_true(contains_bytes(bytes, size, "sRGB"));
    free(bytes);
    bytes = slurp(lin_path, &size);
    assert_false(contains_bytes(bytes, size, "sRGB"));
    assert_false(contains_bytes(bytes, size, "gAMA"));
    free(bytes);
    sk_image_free(&im);
}

static void test_png_metadata_roundtrip(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/meta.png");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 4, 4, 3, &e_));
    sk_image_metadata meta = {0}, got;
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "shitsukan:height_scale_mm", "0.120", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "Comment", "line one\nline two", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "Title", "質感 \xc3\xa9t\xc3\xa9", &e_)); /* iTXt */
    sk_png_write_desc wd = {.bit_depth = 16, .metadata = &meta};
    SK_ASSERT_OK(sk_image_write_png(&im, path, &wd, &e_));
    int depth = 0;
    SK_ASSERT_OK(sk_image_read_png(&back, path, NULL, &got, &depth, &e_));
    assert_int_equal(depth, 16);
    assert_int_equal(got.count, 3);
    for (int i = 0; i < meta.count; i++) {
        const char *v = sk_image_metadata_get(&got, meta.entries[i].key);
        assert_non_null(v);
        assert_string_equal(v, meta.entries[i].value);
    }
    sk_image_free(&back);

    /* A key libpng would reject is refused before any file is made. */
    const char *bad_path = sk_test_path("image/meta_bad.png");
    sk_image_metadata bad = {0};
    SK_ASSERT_OK(sk_image_metadata_set(&bad, " leading space", "v", &e_));
    sk_png_write_desc bd = {.metadata = &bad};
    sk_error err = {0};
    sk_test_expect_failure(sk_image_write_png(&im, bad_path, &bd, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "keyword");
    assert_false(sk_test_file_exists(bad_path));
    sk_image_free(&im);
}

/* CRC-32 of PNG chunks (ISO 3309), to build headers by hand. */
static uint32_t crc32_png(const unsigned char *p, size_t n)
{
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; i++) {
        c ^= p[i];
        for (int k = 0; k < 8; k++) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return c ^ 0xffffffffu;
}

static size_t put_chunk(unsigned char *out, const char *type, const unsigned char *data,
                        uint32_t len)
{
    out[0] = (unsigned char)(len >> 24);
    out[1] = (unsigned char)(len >> 16);
    out[2] = (unsigned char)(len >> 8);
    out[3] = (unsigned char)len;
    memcpy(out + 4, type, 4);
    if (len) memcpy(out + 8, data, len);
    uint32_t crc = crc32_png(out + 4, len + 4);
    out[8 + len] = (unsigned char)(crc >> 24);
    out[9 + len] = (unsigned char)(crc >> 16);
    out[10 + len] = (unsigned char)(crc >> 8);
    out[11 + len] = (unsigned char)crc;
    return 12 + len;
}

static void test_png_dimension_cap(void **state)
{
    (void)state;
    /* Signature, IHDR of 70000 x 70000 RGBA16 (73 GB of pixels), then an empty IDAT. */
    unsigned char file[128];
    static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
    memcpy(file, sig, 8);
    unsigned char ihdr[13] = {0, 1, 0x11, 0x70, 0, 1, 0x11, 0x70, 16, 6, 0, 0, 0};
    size_t n = 8;
    n += put_chunk(file + n, "IHDR", ihdr, 13);
    n += put_chunk(file + n, "IDAT", NULL, 0);
    const char *path = sk_test_path("image/huge_header.png");
    sk_test_write_file(path, file, n);
    sk_image im;
    sk_error err = {0};
    sk_test_expect_failure(sk_image_read_png(&im, path, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_LIMIT, "70000");
    assert_null(im.data);

    /* A text chunk whose length field claims 1.8 GB: refused before libpng allocates it
       (found by fuzzing), and the file ends long before that. */
    unsigned char small[13] = {0, 0, 0, 4, 0, 0, 0, 4, 8, 0, 0, 0, 0};
    n = 8;
    n += put_chunk(file + n, "IHDR", small, 13);
    static const unsigned char text_header[12] = {0x70, 0,   0,   0, 't', 'E',
                                                  'X',  't', 'k', 0, 'v', 'v'};
    memcpy(file + n, text_header, sizeof text_header);
    n += sizeof text_header;
    sk_test_write_file(path, file, n);
    sk_test_expect_failure(sk_image_read_png(&im, path, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, NULL);
    assert_null(im.data);

    /* 40000 x 40000 grey is within the caps (6.4 GB of floats), but 45 bytes cannot hold
       its 1.6 GB of pixels even at deflate's best ratio: rejected before allocating. */
    unsigned char grey[13] = {0, 0, 0x9c, 0x40, 0, 0, 0x9c, 0x40, 8, 0, 0, 0, 0};
    n = 8;
    n += put_chunk(file + n, "IHDR", grey, 13);
    n += put_chunk(file + n, "IDAT", NULL, 0);
    sk_test_write_file(path, file, n);
    sk_test_expect_failure(sk_image_read_png(&im, path, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, "more pixel data than the file can hold");
    assert_null(im.data);
}

/* Writes a size x size RGB noise image as PNG or EXR to `path`; returns the file bytes. */
static unsigned char *noisy_file(const char *path, int size, bool exr, size_t *bytes)
{
    sk_image im;
    SK_ASSERT_OK(sk_image_create(&im, size, size, 3, &e_));
    fill_random(&im, (uint64_t)size, 0.0f, 1.0f);
    if (exr)
        SK_ASSERT_OK(sk_image_write_exr(&im, path, NULL, &e_));
    else
        SK_ASSERT_OK(sk_image_write_png(&im, path, NULL, &e_));
    sk_image_free(&im);
    return slurp(path, bytes);
}

static void test_png_malformed_files(void **state)
{
    (void)state;
    const char *good = sk_test_path("image/noisy.png");
    size_t size;
    unsigned char *bytes = noisy_file(good, 64, false, &size);
    sk_image im;
    sk_error err = {0};

    const char *truncated = sk_test_path("image/truncated.png");
    sk_test_write_file(truncated, bytes, size / 2);
    sk_test_expect_failure(sk_image_read_png(&im, truncated, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, "truncated.png");
    assert_null(im.data);

    const char *header_only = sk_test_path("image/header_only.png");
    sk_test_write_file(header_only, bytes, 20);
    sk_test_expect_failure(sk_image_read_png(&im, header_only, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, NULL);

    /* One flipped bit inside the compressed data: the IDAT CRC no longer matches. */
    const char *flipped = sk_test_path("image/flipped.png");
    bytes[size / 2] ^= 0x10;
    sk_test_write_file(flipped, bytes, size);
    sk_test_expect_failure(sk_image_read_png(&im, flipped, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, NULL);
    free(bytes);

    const char *garbage = sk_test_path("image/garbage.png");
    sk_test_write_file(garbage, "this is not a png at all", 24);
    sk_test_expect_failure(sk_image_read_png(&im, garbage, NULL, NULL, NULL, &err), &err,
                           SK_ERROR_PARSE, "signature");

    /* Missing files are SK_ERROR_NOT_FOUND (other open failures are SK_ERROR_IO). */
    sk_test_expect_failure(
        sk_image_read_png(&im, sk_test_path("image/does_not_exist.png"), NULL, NULL, NULL, &err),
        &err, SK_ERROR_NOT_FOUND, "does_not_exist.png");
}

/* Writes a PNG with libpng directly, for layouts our writer never makes. */
static void write_raw_png(const char *path, int w, int h, int depth, int color_type, int interlace,
                          const png_color *palette, int palette_size, const unsigned char *trns,
                          int trns_count, const png_color_16 *trns_grey,
                          const unsigned char *pixels)
{
    FILE *fp = fopen(path, "wb");
    assert_non_null(fp);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) fail_msg("libpng failed writing %s", path);
    png_init_io(png, fp);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, depth, color_type, interlace,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (palette) png_set_PLTE(png, info, palette, palette_size);
    if (trns || trns_grey) png_set_tRNS(png, info, trns, trns_count, trns_grey);
    png_write_info(png, info);
    size_t row_bytes = png_get_rowbytes(png, info);
    int passes = png_set_interlace_handling(png);
    for (int p = 0; p < passes; p++)
        for (int y = 0; y < h; y++) png_write_row(png, pixels + (size_t)y * row_bytes);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(fp);
}

static void test_png_foreign_layouts(void **state)
{
    (void)state;
    sk_png_read_desc raw = {.encoding = SK_PNG_ENCODING_LINEAR};
    sk_image im;
    int depth;

    /* 2-bit palette with transparency -> RGBA. Row of 4 pixels = 1 byte: 0,1,2,3. */
    png_color pal[4] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {10, 20, 30}};
    unsigned char alpha[4] = {255, 128, 0, 255};
    unsigned char row2[2] = {0x1b, 0xe4}; /* 00 01 10 11 / 11 10 01 00 */
    const char *pal_path = sk_test_path("image/palette.png");
    write_raw_png(pal_path, 4, 2, 2, PNG_COLOR_TYPE_PALETTE, PNG_INTERLACE_NONE, pal, 4, alpha, 4,
                  NULL, row2);
    SK_ASSERT_OK(sk_image_read_png(&im, pal_path, &raw, NULL, &depth, &e_));
    assert_int_equal(depth, 2);
    assert_int_equal(im.channels, 4);
    const float *p = sk_image_pixel(&im, 3, 0);
    assert_float_equal(p[0] * 255.0f, 10.0f, 1e-3);
    assert_float_equal(p[1] * 255.0f, 20.0f, 1e-3);
    assert_float_equal(p[2] * 255.0f, 30.0f, 1e-3);
    assert_float_equal(p[3], 1.0f, 1e-6);
    p = sk_image_pixel(&im, 1, 1); /* index 2: blue, alpha 0 */
    assert_float_equal(p[2], 1.0f, 1e-6);
    assert_float_equal(p[3], 0.0f, 1e-6);
    sk_image_free(&im);

    /* 1-bit grey: 0 -> 0.0, 1 -> 1.0. */
    unsigned char bits[2] = {0xa0, 0x50}; /* 1010.... / 0101.... */
    const char *grey_path = sk_test_path("image/grey1.png");
    write_raw_png(grey_path, 4, 2, 1, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, NULL, 0, NULL, 0,
                  NULL, bits);
    SK_ASSERT_OK(sk_image_read_png(&im, grey_path, &raw, NULL, &depth, &e_));
    assert_int_equal(depth, 1);
    assert_int_equal(im.channels, 1);
    const float want[8] = {1, 0, 1, 0, 0, 1, 0, 1};
    for (int i = 0; i < 8; i++) assert_float_equal(im.data[i], want[i], 0.0);
    sk_image_free(&im);

    /* 16-bit grey with a tRNS key colour -> grey + alpha, and Adam7 interlacing. */
    enum { W = 9, H = 7 };
    unsigned char g16[W * H * 2];
    for (int i = 0; i < W * H; i++) {
        unsigned v = (unsigned)i * 1000u;
        g16[2 * i] = (unsigned char)(v >> 8);
        g16[2 * i + 1] = (unsigned char)v;
    }
    png_color_16 key = {.gray = 5000};
    const char *inter_path = sk_test_path("image/interlaced16.png");
    write_raw_png(inter_path, W, H, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_ADAM7, NULL, 0, NULL, 0,
                  &key, g16);
    SK_ASSERT_OK(sk_image_read_png(&im, inter_path, &raw, NULL, &depth, &e_));
    assert_int_equal(depth, 16);
    assert_int_equal(im.channels, 2);
    for (int i = 0; i < W * H; i++) {
        assert_float_equal(im.data[2 * i], (float)(i * 1000) / 65535.0f, 1e-7);
        assert_float_equal(im.data[2 * i + 1], i == 5 ? 0.0f : 1.0f, 0.0);
    }
    sk_image_free(&im);
}

/* ------------------------------------------------------------------ EXR */

static void test_exr_float_roundtrip_bit_exact(void **state)
{
    (void)state;
    const sk_exr_compression comps[6] = {SK_EXR_COMPRESSION_NONE, SK_EXR_COMPRESSION_ZIP,
                                         SK_EXR_COMPRESSION_PIZ,  SK_EXR_COMPRESSION_RLE,
                                         SK_EXR_COMPRESSION_ZIPS, SK_EXR_COMPRESSION_DEFAULT};
    for (int channels = 1; channels <= 4; channels++)
        for (int k = 0; k < 6; k++) {
            char name[64];
            snprintf(name, sizeof name, "image/float_%d_%d.exr", channels, k);
            const char *path = sk_test_path(name);
            sk_image im, back;
            SK_ASSERT_OK(sk_image_create(&im, 37, 21, channels, &e_));
            fill_random(&im, (uint64_t)(channels * 10 + k), -1000.0f, 1000.0f);
            im.data[0] = 1e-40f; /* a denormal */
            im.data[1 % (37 * 21 * channels)] = -3.4e38f;
            sk_exr_write_desc wd = {.compression = comps[k]};
            SK_ASSERT_OK(sk_image_write_exr(&im, path, &wd, &e_));
            SK_ASSERT_OK(sk_image_read_exr(&back, path, NULL, &e_));
            assert_int_equal(back.width, 37);
            assert_int_equal(back.height, 21);
            assert_int_equal(back.channels, channels);
            assert_memory_equal(back.data, im.data, sizeof(float) * 37 * 21 * channels);
            sk_image_free(&im);
            sk_image_free(&back);
        }
}

/* Images of many chunks are encoded in parallel: every compression and level reads back
 * bit for bit, half too, and the bytes are the same on 1 and 2 threads; smooth data
 * compresses, and a bad level is refused. */
static void test_exr_parallel_chunks(void **state)
{
    (void)state;
    sk_image im, back;
    /* 5 MB of floats (1.7 MB under the sanitizers), more than one thread's share */
    const int W = getenv("SK_TEST_SANITIZED") ? 400 : 700,
              H = getenv("SK_TEST_SANITIZED") ? 350 : 600;
    SK_ASSERT_OK(sk_image_create(&im, W, H, 3, &e_));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            for (int c = 0; c < 3; c++)
                sk_image_pixel(&im, x, y)[c] =
                    (float)floor(1024.0 * sin(0.01 * x + c) * cos(0.013 * y)) / 1024.0f;
    const struct {
        sk_exr_compression c;
        int level, tile;
        sk_exr_pixel_type type;
    } kinds[] = {{SK_EXR_COMPRESSION_ZIP, 1, 0, 0},
                 {SK_EXR_COMPRESSION_ZIP, 9, 0, 0},
                 {SK_EXR_COMPRESSION_ZIPS, 4, 0, 0},
                 {SK_EXR_COMPRESSION_DEFAULT, 0, 0, 0},
                 {SK_EXR_COMPRESSION_PIZ, 0, 0, 0},
                 {SK_EXR_COMPRESSION_RLE, 0, 0, 0},
                 {SK_EXR_COMPRESSION_NONE, 0, 0, 0},
                 {SK_EXR_COMPRESSION_ZIP, 0, 64, 0},
                 {SK_EXR_COMPRESSION_DEFAULT, 0, 0, SK_EXR_PIXEL_HALF}};
    int threads = sk_threads_max();
    long none_size = 0;
    for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
        const char *one = sk_test_path("image/chunks1.exr"),
                   *two = sk_test_path("image/chunks2.exr");
        sk_exr_write_desc wd = {.compression = kinds[k].c,
                                .compression_level = kinds[k].level,
                                .tile_size = kinds[k].tile,
                                .pixel_type = kinds[k].type};
        sk_threads_set(1);
        SK_ASSERT_OK(sk_image_write_exr(&im, one, &wd, &e_));
        sk_threads_set(2);
        SK_ASSERT_OK(sk_image_write_exr(&im, two, &wd, &e_));
        sk_threads_set(threads);
        assert_true(sk_test_same_file(one, two));
        SK_ASSERT_OK(sk_image_read_exr(&back, two, NULL, &e_));
        for (size_t i = 0; i < (size_t)W * H * 3; i++) {
            float want = im.data[i];
            if (kinds[k].type == SK_EXR_PIXEL_HALF) {
                if (fabsf(back.data[i] - want) > fabsf(want) * 0x1p-11f + 0x1p-25f)
                    fail_msg("kind %zu sample %zu: %.9g came back as %.9g", k, i, want,
                             back.data[i]);
            } else if (back.data[i] != want) {
                fail_msg("kind %zu sample %zu: %.9g came back as %.9g", k, i, want, back.data[i]);
            }
        }
        sk_image_free(&back);
        if (kinds[k].c == SK_EXR_COMPRESSION_NONE) none_size = file_size(two);
        if (k == 3) assert_true(file_size(two) < W * H * 3 * 4 * 0.9); /* the default compresses */
    }
    assert_true(none_size >= W * H * 3 * 4);
    sk_error err = {0};
    sk_exr_write_desc bad = {.compression = SK_EXR_COMPRESSION_ZIP, .compression_level = 10};
    assert_int_equal(sk_image_write_exr(&im, sk_test_path("image/bad.exr"), &bad, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "compression_level = 10 is out of range [1, 9]"));
    sk_image_free(&im);
}

static void test_exr_half_roundtrip(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/half.exr");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 64, 32, 3, &e_));
    fill_random(&im, 5, -100.0f, 100.0f);
    /* Values a half holds exactly, the largest half, a half denormal, and a tie. */
    const float exact[6] = {0.5f, -2.0f, 1024.0f, 65504.0f, 0x1p-24f, 0.333251953125f};
    for (int i = 0; i < 6; i++) im.data[i] = exact[i];
    im.data[6] = 1.0f + 0x1p-11f;     /* halfway between 1 and 1 + 2^-10: ties to even = 1 */
    im.data[7] = 1.0f + 3 * 0x1p-11f; /* halfway, ties to even = 1 + 2^-9 */
    im.data[8] = 1e6f;                /* beyond the half range */
    sk_exr_write_desc wd = {.pixel_type = SK_EXR_PIXEL_HALF, .compression = SK_EXR_COMPRESSION_PIZ};
    SK_ASSERT_OK(sk_image_write_exr(&im, path, &wd, &e_));
    SK_ASSERT_OK(sk_image_read_exr(&back, path, NULL, &e_));
    for (int i = 0; i < 6; i++) assert_true(back.data[i] == exact[i]);
    assert_true(back.data[6] == 1.0f);
    assert_true(back.data[7] == 1.0f + 0x1p-9f);
    assert_true(isinf(back.data[8]) && back.data[8] > 0);
    for (size_t i = 9; i < (size_t)64 * 32 * 3; i++) {
        float a = im.data[i], b = back.data[i];
        /* Half keeps 11 significant bits: rounding error at most 2^-11 relative. */
        if (fabsf(a - b) > fabsf(a) * 0x1p-11f + 0x1p-25f)
            fail_msg("sample %zu: %.9g came back as %.9g", i, a, b);
    }
    sk_image_free(&im);
    sk_image_free(&back);
    /* Half files are about half the size of float files. */
    assert_true(file_size(path) > 0);
}

static void test_exr_metadata_roundtrip(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/meta.exr");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 8, 8, 1, &e_));
    sk_image_metadata meta = {0}, got;
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "shitsukan:height_scale_mm", "0.120", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "owner", "質感", &e_));
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "a_long_attribute_name_beyond_31_bytes", "x", &e_));
    sk_exr_write_desc wd = {.metadata = &meta};
    SK_ASSERT_OK(sk_image_write_exr(&im, path, &wd, &e_));
    SK_ASSERT_OK(sk_image_read_exr(&back, path, &got, &e_));
    for (int i = 0; i < meta.count; i++) {
        const char *v = sk_image_metadata_get(&got, meta.entries[i].key);
        if (!v) fail_msg("metadata \"%s\" lost", meta.entries[i].key);
        assert_string_equal(v, meta.entries[i].value);
    }
    sk_image_free(&back);

    sk_image_metadata bad = {0};
    SK_ASSERT_OK(sk_image_metadata_set(&bad, "dataWindow", "0 0 1 1", &e_));
    sk_exr_write_desc bd = {.metadata = &bad};
    sk_error err = {0};
    const char *bad_path = sk_test_path("image/meta_bad.exr");
    sk_test_expect_failure(sk_image_write_exr(&im, bad_path, &bd, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "dataWindow");
    assert_false(sk_test_file_exists(bad_path));
    sk_image_free(&im);
}

static void test_exr_channel_order(void **state)
{
    (void)state;
    /* Channel c holds value c + 1; EXR stores them sorted by name (B, G, R / A, Y). */
    for (int channels = 1; channels <= 4; channels++) {
        char name[64];
        snprintf(name, sizeof name, "image/order_%d.exr", channels);
        const char *path = sk_test_path(name);
        sk_image im, back;
        SK_ASSERT_OK(sk_image_create(&im, 5, 3, channels, &e_));
        for (int i = 0; i < 15 * channels; i++) im.data[i] = (float)(i % channels + 1);
        SK_ASSERT_OK(sk_image_write_exr(&im, path, NULL, &e_));
        SK_ASSERT_OK(sk_image_read_exr(&back, path, NULL, &e_));
        assert_int_equal(back.channels, channels);
        assert_memory_equal(back.data, im.data, sizeof(float) * 15 * channels);
        sk_image_free(&im);
        sk_image_free(&back);
    }
    /* Custom names in a scrambled order come back as R, G, B, A. */
    const char *path = sk_test_path("image/order_named.exr");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 2, 2, 4, &e_));
    for (int i = 0; i < 16; i++) im.data[i] = (float)(i % 4);
    const char *names[4] = {"A", "B", "R", "G"};
    sk_exr_write_desc wd = {.channel_names = names};
    SK_ASSERT_OK(sk_image_write_exr(&im, path, &wd, &e_));
    SK_ASSERT_OK(sk_image_read_exr(&back, path, NULL, &e_));
    const float *px = sk_image_pixel(&back, 1, 1);
    assert_float_equal(px[0], 2.0f, 0.0); /* R */
    assert_float_equal(px[1], 3.0f, 0.0); /* G */
    assert_float_equal(px[2], 1.0f, 0.0); /* B */
    assert_float_equal(px[3], 0.0f, 0.0); /* A */
    sk_image_free(&im);
    sk_image_free(&back);
}

static void test_exr_tiled_roundtrip(void **state)
{
    (void)state;
    const char *path = sk_test_path("image/tiled.exr");
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 37, 23, 4, &e_));
    fill_random(&im, 11, -5.0f, 5.0f);
    sk_exr_write_desc wd = {.tile_size = 16, .compression = SK_EXR_COMPRESSION_ZIP};
    SK_ASSERT_OK(sk_image_write_exr(&im, path, &wd, &e_));
    SK_ASSERT_OK(sk_image_read_exr(&back, path, NULL, &e_));
    assert_int_equal(back.width, 37);
    assert_int_equal(back.height, 23);
    assert_memory_equal(back.data, im.data, sizeof(float) * 37 * 23 * 4);
    sk_image_free(&back);
    sk_error err = {0};
    wd.tile_size = 3;
    sk_test_expect_failure(sk_image_write_exr(&im, path, &wd, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "tile_size");
    sk_image_free(&im);
}

/* Writes, with the OpenEXR C API directly, a file our writer never makes: UINT and HALF
 * channels plus an extra "Z", a data window offset from the origin inside a larger
 * display window. */
static void write_foreign_exr(const char *path, int w, int h, const uint32_t *r_uint,
                              const float *g, const float *z)
{
    exr_context_t ctxt;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    assert_int_equal(exr_start_write(&ctxt, path, EXR_WRITE_FILE_DIRECTLY, &init), 0);
    int part;
    assert_int_equal(exr_add_part(ctxt, NULL, EXR_STORAGE_SCANLINE, &part), 0);
    exr_attr_box2i_t display, data;
    display.min.x = 0;
    display.min.y = 0;
    display.max.x = 99;
    display.max.y = 99;
    data.min.x = 10;
    data.min.y = 20;
    data.max.x = 10 + w - 1;
    data.max.y = 20 + h - 1;
    exr_attr_v2f_t center;
    center.x = 0.0f;
    center.y = 0.0f;
    assert_int_equal(exr_initialize_required_attr(ctxt, part, &display, &data, 1.0f, &center, 1.0f,
                                                  EXR_LINEORDER_INCREASING_Y, EXR_COMPRESSION_NONE),
                     0);
    assert_int_equal(exr_add_channel(ctxt, part, "R", EXR_PIXEL_UINT, 1, 1, 1), 0);
    assert_int_equal(exr_add_channel(ctxt, part, "G", EXR_PIXEL_HALF, 1, 1, 1), 0);
    assert_int_equal(exr_add_channel(ctxt, part, "Z", EXR_PIXEL_FLOAT, 1, 1, 1), 0);
    assert_int_equal(exr_write_header(ctxt), 0);
    exr_encode_pipeline_t enc = EXR_ENCODE_PIPELINE_INITIALIZER;
    for (int y = 0; y < h; y++) {
        exr_chunk_info_t cinfo;
        assert_int_equal(exr_write_scanline_chunk_info(ctxt, part, 20 + y, &cinfo), 0);
        if (y == 0)
            assert_int_equal(exr_encoding_initialize(ctxt, part, &cinfo, &enc), 0);
        else
            assert_int_equal(exr_encoding_update(ctxt, part, &cinfo, &enc), 0);
        for (int c = 0; c < enc.channel_count; c++) {
            exr_coding_channel_info_t *ch = &enc.channels[c];
            bool is_r = strcmp(ch->channel_name, "R") == 0;
            const void *src =
                is_r ? (const void *)(r_uint + y * w)
                     : (const void *)((strcmp(ch->channel_name, "G") == 0 ? g : z) + y * w);
            ch->user_data_type = is_r ? EXR_PIXEL_UINT : EXR_PIXEL_FLOAT;
            ch->user_bytes_per_element = 4;
            ch->user_pixel_stride = 4;
            ch->user_line_stride = 4 * w;
            ch->encode_from_ptr = src;
        }
        if (y == 0) assert_int_equal(exr_encoding_choose_default_routines(ctxt, part, &enc), 0);
        assert_int_equal(exr_encoding_run(ctxt, part, &enc), 0);
    }
    exr_encoding_destroy(ctxt, &enc);
    assert_int_equal(exr_finish(&ctxt), 0);
}

static void test_exr_foreign_file(void **state)
{
    (void)state;
    enum { W = 6, H = 4 };
    uint32_t r[W * H];
    float g[W * H], z[W * H];
    for (int i = 0; i < W * H; i++) {
        r[i] = (uint32_t)i * 1000u;
        g[i] = (float)i * 0.25f;
        z[i] = -(float)i;
    }
    const char *path = sk_test_path("image/foreign.exr");
    write_foreign_exr(path, W, H, r, g, z);
    sk_image im;
    SK_ASSERT_OK(sk_image_read_exr(&im, path, NULL, &e_));
    assert_int_equal(im.width, W); /* the data window, not the 100 x 100 display window */
    assert_int_equal(im.height, H);
    assert_int_equal(im.channels, 3); /* R, G, then Z */
    for (int i = 0; i < W * H; i++) {
        assert_float_equal(im.data[3 * i], (float)r[i], 0.0);
        assert_float_equal(im.data[3 * i + 1], g[i], 0.0);
        assert_float_equal(im.data[3 * i + 2], z[i], 0.0);
    }
    sk_image_free(&im);
}

static void test_exr_malformed_files(void **state)
{
    (void)state;
    const char *good = sk_test_path("image/good.exr");
    size_t size;
    unsigned char *bytes = noisy_file(good, 40, true, &size);
    sk_image im;
    sk_error err = {0};

    const char *truncated = sk_test_path("image/truncated.exr");
    sk_test_write_file(truncated, bytes, size - size / 3);
    sk_test_expect_failure(sk_image_read_exr(&im, truncated, NULL, &err), &err, SK_ERROR_PARSE,
                           "truncated.exr");
    assert_null(im.data);

    const char *header_cut = sk_test_path("image/header_cut.exr");
    sk_test_write_file(header_cut, bytes, 60);
    sk_test_expect_failure(sk_image_read_exr(&im, header_cut, NULL, &err), &err, SK_ERROR_PARSE,
                           NULL);

    /* Garbage over the compressed pixel data (after the header and offset table). */
    const char *scrambled = sk_test_path("image/scrambled.exr");
    for (size_t i = size / 2; i < size; i++) bytes[i] = (unsigned char)(i * 37u);
    sk_test_write_file(scrambled, bytes, size);
    sk_test_expect_failure(sk_image_read_exr(&im, scrambled, NULL, &err), &err, SK_ERROR_PARSE,
                           NULL);
    free(bytes);

    /* A data window of 20000 x 20000 patched into a 40 x 40 file: within the caps, but
       the file cannot hold those pixels; rejected before the image is allocated. */
    bytes = slurp(good, &size);
    const char *dw = "dataWindow";
    unsigned char *at = NULL;
    for (size_t i = 0; i + 30 < size && !at; i++)
        if (memcmp(bytes + i, dw, strlen(dw) + 1) == 0) at = bytes + i;
    assert_non_null(at);
    at += strlen(dw) + 1 + strlen("box2i") + 1 + 4; /* name, type, size: then xmin ymin xmax ymax */
    int32_t big = 19999;
    memcpy(at + 8, &big, 4);
    memcpy(at + 12, &big, 4);
    const char *huge = sk_test_path("image/huge_window.exr");
    sk_test_write_file(huge, bytes, size);
    free(bytes);
    sk_test_expect_failure(sk_image_read_exr(&im, huge, NULL, &err), &err, SK_ERROR_PARSE, NULL);
    assert_null(im.data);

    const char *garbage = sk_test_path("image/garbage.exr");
    sk_test_write_file(garbage, "v/1\x01 not really an exr file", 27);
    sk_test_expect_failure(sk_image_read_exr(&im, garbage, NULL, &err), &err, SK_ERROR_PARSE, NULL);
    sk_test_expect_failure(sk_image_read_exr(&im, sk_test_path("image/missing.exr"), NULL, &err),
                           &err, SK_ERROR_NOT_FOUND, "missing.exr");
}

/* ------------------------------------------------------------------ atomic writing */

static void test_atomic_file_abort(void **state)
{
    (void)state;
    const char *path = sk_test_path("atomic/aborted.bin");
    char folder[1024];
    folder_of(path, folder, sizeof folder);
    sk_atomic_file f;
    SK_ASSERT_OK(sk_atomic_file_open(&f, path, &e_));
    assert_non_null(f.fp);
    fputs("partial", f.fp);
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 1);
    sk_atomic_file_abort(&f);
    assert_null(f.fp);
    assert_false(sk_test_file_exists(path));
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 0);
    sk_atomic_file_abort(&f); /* safe twice */
}

static void test_write_into_missing_folder(void **state)
{
    (void)state;
    sk_image im;
    SK_ASSERT_OK(sk_image_create(&im, 4, 4, 3, &e_));
    const char *png = sk_test_path("image/no_such_folder/x.png");
    /* sk_test_path made the folder; remove it so the write must fail. */
    char folder[1024];
    folder_of(png, folder, sizeof folder);
    rmdir(folder);
    sk_error err = {0};
    sk_test_expect_failure(sk_image_write_png(&im, png, NULL, &err), &err, SK_ERROR_IO, "x.png");
    assert_false(sk_test_file_exists(png));
    char exr[1100];
    snprintf(exr, sizeof exr, "%s/x.exr", folder);
    sk_test_expect_failure(sk_image_write_exr(&im, exr, NULL, &err), &err, SK_ERROR_IO, "x.exr");
    assert_false(sk_test_file_exists(exr));
    sk_image_free(&im);
}

/* A write that fails midway (the file size limit stops it) keeps the old file and leaves
 * no temporary file behind. */
static void test_failed_write_keeps_old_file(void **state)
{
    (void)state;
    const char *png = sk_test_path("midway/image.png");
    const char *exr = sk_test_path("midway/image.exr");
    char folder[1024];
    folder_of(png, folder, sizeof folder);
    sk_image small, big;
    SK_ASSERT_OK(sk_image_create(&small, 2, 2, 1, &e_));
    SK_ASSERT_OK(sk_image_write_png(&small, png, NULL, &e_));
    SK_ASSERT_OK(sk_image_write_exr(&small, exr, NULL, &e_));
    long png_size = file_size(png), exr_size = file_size(exr);
    SK_ASSERT_OK(sk_image_create(&big, 256, 256, 4, &e_));
    fill_random(&big, 1, 0.0f, 1.0f); /* noise does not compress below the limit */

    struct rlimit old_limit, limit;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
    void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);
    limit = old_limit;
    limit.rlim_cur = 8192;
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &limit), 0);
    sk_error perr = {0}, eerr = {0};
    sk_result pr = sk_image_write_png(&big, png, NULL, &perr);
    sk_result er = sk_image_write_exr(&big, exr, NULL, &eerr);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &old_limit), 0);
    signal(SIGXFSZ, old_handler);

    sk_test_expect_failure(pr, &perr, SK_ERROR_IO, "image.png");
    sk_test_expect_failure(er, &eerr, SK_ERROR_IO, "image.exr");
    assert_int_equal(file_size(png), png_size);
    assert_int_equal(file_size(exr), exr_size);
    assert_int_equal(sk_test_count_files_containing(folder, ".tmp"), 0);
    sk_image back;
    SK_ASSERT_OK(sk_image_read_png(&back, png, NULL, NULL, NULL, &e_));
    assert_int_equal(back.width, 2);
    sk_image_free(&back);
    sk_image_free(&small);
    sk_image_free(&big);
}

static void test_write_auto_by_extension(void **state)
{
    (void)state;
    sk_image im, back;
    SK_ASSERT_OK(sk_image_create(&im, 3, 3, 3, &e_));
    fill_random(&im, 2, 0.0f, 1.0f);
    sk_image_metadata meta = {0}, got;
    SK_ASSERT_OK(sk_image_metadata_set(&meta, "k", "v", &e_));
    const char *exr = sk_test_path("image/auto.EXR");
    SK_ASSERT_OK(sk_image_write_auto(&im, exr, &meta, &e_));
    SK_ASSERT_OK(sk_image_read_exr(&back, exr, &got, &e_));
    assert_memory_equal(back.data, im.data, sizeof(float) * 27); /* float EXR: exact */
    assert_string_equal(sk_image_metadata_get(&got, "k"), "v");
    sk_image_free(&back);
    const char *png = sk_test_path("image/auto.png");
    SK_ASSERT_OK(sk_image_write_auto(&im, png, &meta, &e_));
    int depth;
    SK_ASSERT_OK(sk_image_read_png(&back, png, NULL, &got, &depth, &e_));
    assert_int_equal(depth, 8);
    assert_string_equal(sk_image_metadata_get(&got, "k"), "v");
    sk_image_free(&back);
    sk_error err = {0};
    sk_test_expect_failure(sk_image_write_auto(&im, sk_test_path("image/auto.tiff"), NULL, &err),
                           &err, SK_ERROR_UNSUPPORTED, ".png, .exr");
    sk_png_write_desc bad = {.bit_depth = 12};
    sk_test_expect_failure(sk_image_write_png(&im, png, &bad, &err), &err,
                           SK_ERROR_INVALID_ARGUMENT, "bit_depth");
    sk_image_free(&im);
}

/* The codes for callers that encode files themselves are the PNG writer's codes: every
 * encoding and depth, read back raw (LINEAR decoding gives code / max). */
static void test_codes_match_png_writer(void **state)
{
    (void)state;
    sk_image img;
    assert_int_equal(sk_image_create(&img, 613, 3, 4, NULL), SK_OK);
    size_t n = (size_t)img.width * img.height * 4;
    for (size_t i = 0; i < n; i++) img.data[i] = (float)i / (float)(n - 40) - 0.01f;
    img.data[5] = NAN;
    const sk_png_encoding encodings[2] = {SK_PNG_ENCODING_SRGB, SK_PNG_ENCODING_LINEAR};
    uint8_t *c8 = malloc(n);
    uint16_t *c16 = malloc(n * 2);
    for (int e = 0; e < 2; e++)
        for (int depth = 8; depth <= 16; depth += 8) {
            const char *path = sk_test_path(depth == 8 ? "codes/c8.png" : "codes/c16.png");
            sk_png_write_desc wd = {.bit_depth = depth, .encoding = encodings[e]};
            assert_int_equal(sk_image_write_png(&img, path, &wd, NULL), SK_OK);
            sk_image back;
            sk_png_read_desc rd = {.encoding = SK_PNG_ENCODING_LINEAR};
            assert_int_equal(sk_image_read_png(&back, path, &rd, NULL, NULL, NULL), SK_OK);
            if (depth == 8)
                sk_image_codes8(img.data, (size_t)img.width * img.height, 4, encodings[e], c8);
            else
                sk_image_codes16(img.data, (size_t)img.width * img.height, 4, encodings[e], c16);
            double max = depth == 8 ? 255.0 : 65535.0;
            for (size_t i = 0; i < n; i++) {
                long file_code = lround(back.data[i] * max);
                long code = depth == 8 ? c8[i] : c16[i];
                assert_int_equal(code, file_code);
            }
            sk_image_free(&back);
        }
    free(c8);
    free(c16);
    sk_image_free(&img);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_image_create_caps),
        cmocka_unit_test(test_metadata_set_get),
        cmocka_unit_test(test_srgb_curve),
        cmocka_unit_test(test_codes_match_png_writer),
        cmocka_unit_test(test_png_roundtrip_all_layouts),
        cmocka_unit_test(test_png_16bit_gradient_exact),
        cmocka_unit_test(test_png_compression_level),
        cmocka_unit_test(test_png_16bit_srgb_table),
        cmocka_unit_test(test_png_srgb_encoding_known_code),
        cmocka_unit_test(test_png_metadata_roundtrip),
        cmocka_unit_test(test_png_dimension_cap),
        cmocka_unit_test(test_png_malformed_files),
        cmocka_unit_test(test_png_foreign_layouts),
        cmocka_unit_test(test_exr_float_roundtrip_bit_exact),
        cmocka_unit_test(test_exr_parallel_chunks),
        cmocka_unit_test(test_exr_half_roundtrip),
        cmocka_unit_test(test_exr_metadata_roundtrip),
        cmocka_unit_test(test_exr_channel_order),
        cmocka_unit_test(test_exr_tiled_roundtrip),
        cmocka_unit_test(test_exr_foreign_file),
        cmocka_unit_test(test_exr_malformed_files),
        cmocka_unit_test(test_atomic_file_abort),
        cmocka_unit_test(test_write_into_missing_folder),
        cmocka_unit_test(test_failed_write_keeps_old_file),
        cmocka_unit_test(test_write_auto_by_extension),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
