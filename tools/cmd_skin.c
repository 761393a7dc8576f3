/* `shitsukan skin` (shaded preview, as the paper's figures) and `shitsukan skin maps`
 * (height, normal, furrow, cell and preview maps for renderers) of the skin microrelief
 * model of Ishii et al. 1991. Parses arguments, loads presets, calls the library, writes
 * files. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "shitsukan/io.h"
#include "shitsukan/skin.h"

#define SKIN_DEFAULT_SIZE 400
#define SKIN_BAND_ROWS 64
/* Maps of at least this many pixels are written with a fast zlib level. */
#define SKIN_FAST_PNG_PIXELS (2048 * 2048)

static const cli_option k_preview_options[] = {
    {"size", 0, "N|WxH", "image size in pixels; default 400 (the paper's)", false},
    {"mm-per-px", 0, "MM", "pixel size in mm (the tile becomes size x MM); default from size_mm",
     false},
    {"region", 0, "x,y,w,h", "render only this sub-rectangle (same pixels as the full image)",
     false},
    {"samples", 0, "N", "samples per pixel side (anti-aliasing), 1..8; default 1", false},
    {"edges", 0, NULL, "draw each level's furrows in colour over the shading", false},
};

static const cli_option k_maps_options[] = {
    {"size", 0, "N|WxH", "map size in pixels; default 1024", false},
    {"mm-per-px", 0, "MM", "pixel size in mm (the tile becomes size x MM); default from size_mm",
     false},
    {"region", 0, "x,y,w,h", "render only this sub-rectangle (same pixels as the full map)", false},
    {"directx", 0, NULL, "normal map in the DirectX convention (green down); default OpenGL",
     false},
    {"edges", 0, NULL, "also write edges.png, the preview with every level's furrows drawn", false},
    {"furrow-level", 0, "K", "level whose furrows furrow.png measures; default 1", false},
    {"id-level", 0, "K", "level whose cells cells.png colours; default 1", false},
    {"samples", 0, "N", "preview samples per pixel side, 1..8; default 1", false},
};

/* Loads the preset and --set/--seed edits into a desc; applies --size/--mm-per-px. */
static int load_desc(const cli_command *command, const cli_args *args, int default_size,
                     sk_skin_desc *desc, int *width, int *height)
{
    sk_preset *preset;
    int status = cli_load_preset(command, args, &preset);
    if (status) return status;
    memset(desc, 0, sizeof *desc);
    sk_error err = {0};
    sk_result r = sk_preset_bind(preset, &sk_skin_schema, desc, &err);
    sk_preset_free(preset);
    if (r != SK_OK) return cli_fail_error(&err);
    if ((status = cli_get_size(command, args, "size", default_size, default_size,
                               SK_IMAGE_MAX_DIMENSION, width, height)))
        return status;
    if (cli_has(command, args, "mm-per-px")) {
        double mm;
        if ((status = cli_get_double(command, args, "mm-per-px", 0, 1e-6, 100, &mm))) return status;
        desc->size_mm[0] = (float)(mm * *width);
        desc->size_mm[1] = (float)(mm * *height);
    }
    /* the cells get what the cap leaves (the images are checked by the caller) */
    desc->max_memory = (double)args->common.max_memory;
    return 0;
}

/* The images of a w x h region of `bytes_per_pixel`, against the cap; the rest of the cap
   is left to the skin's cells. */
static int check_image_memory(const cli_args *args, int w, int h, double bytes_per_pixel,
                              sk_skin_desc *desc)
{
    double bytes = cli_image_bytes(w, h, bytes_per_pixel);
    char driver[96];
    snprintf(driver, sizeof driver, "a %d x %d image (--size, --region)", w, h);
    int status = cli_check_image(w, h, 3, driver);
    if (!status) status = cli_check_memory(args, bytes, driver);
    if (status) return status;
    desc->max_memory -= bytes;
    if (desc->max_memory < 1.0) desc->max_memory = 1.0;
    return 0;
}

static int make_skin(const sk_skin_desc *desc, const cli_args *args, sk_skin **skin)
{
    sk_error err = {0};
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "skin cells", !args->common.quiet);
    sk_skin_desc d = *desc;
    d.progress = sk_progress_bar_sink(&bar);
    sk_result r = sk_skin_create(skin, &d, &err);
    sk_progress_bar_end(&bar);
    return r == SK_OK ? 0 : cli_fail_error(&err);
}

static int get_region(const cli_command *command, const cli_args *args, int w, int h, int region[4])
{
    region[0] = 0, region[1] = 0, region[2] = w, region[3] = h;
    const char *text = cli_get(command, args, "region");
    return text ? cli_parse_region(text, w, h, region) : 0;
}

static void describe(const sk_skin *skin, int w, int h, sk_image_metadata *meta)
{
    const sk_skin_desc *d = sk_skin_get_desc(skin);
    char v[128];
    double tw, th;
    sk_skin_tile_size(skin, &tw, &th);
    snprintf(v, sizeof v, "%llu", (unsigned long long)d->seed);
    sk_image_metadata_set(meta, "shitsukan:seed", v, NULL);
    snprintf(v, sizeof v, "%.9g x %.9g", tw, th);
    sk_image_metadata_set(meta, "shitsukan:tile_mm", v, NULL);
    snprintf(v, sizeof v, "%.9g", tw / w);
    sk_image_metadata_set(meta, "shitsukan:mm_per_px", v, NULL);
    sk_image_metadata_set(meta, "shitsukan:seamless", d->aperiodic ? "false" : "true", NULL);
    sk_image_metadata_set(meta, "Software", "shitsukan " SK_VERSION_STRING, NULL);
    (void)h;
}

/* ------------------------------------------------------------------ preview */
static int run_preview(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "skin: -o/--output FILE.png is required");
    sk_skin_desc desc;
    int w, h, region[4], status;
    long long samples;
    if ((status = load_desc(command, args, SKIN_DEFAULT_SIZE, &desc, &w, &h))) return status;
    if ((status = get_region(command, args, w, h, region))) return status;
    if ((status = cli_get_int(command, args, "samples", 1, 1, 8, &samples))) return status;
    int format;
    static const char *const k_png[] = {".png", NULL};
    if ((status = cli_output_format("-o", output, k_png, &format))) return status;
    /* float RGB and its 8-bit encoding */
    if ((status = check_image_memory(args, region[2], region[3], 16, &desc))) return status;
    sk_skin *skin;
    if ((status = make_skin(&desc, args, &skin))) return status;
    sk_error err = {0};
    sk_image image = {0};
    sk_result r = sk_image_create(&image, region[2], region[3], 3, &err);
    if (r == SK_OK) {
        sk_progress_bar bar;
        sk_progress_bar_begin(&bar, "skin", !args->common.quiet);
        sk_skin_render_desc rd = {.width = w, .height = h, .samples = (int)samples};
        memcpy(rd.region, region, sizeof rd.region);
        if (cli_has(command, args, "edges"))
            rd.edges = image.data;
        else
            rd.preview = image.data;
        rd.progress = sk_progress_bar_sink(&bar);
        r = sk_skin_render(skin, &rd, &err);
        sk_progress_bar_end(&bar);
    }
    if (r == SK_OK) {
        sk_image_metadata meta = {0};
        describe(skin, w, h, &meta);
        sk_png_write_desc png = {
            .bit_depth = 8, .encoding = SK_PNG_ENCODING_SRGB, .metadata = &meta};
        r = sk_image_write_png(&image, output, &png, &err);
    }
    sk_image_free(&image);
    sk_skin_destroy(skin);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

/* --------------------------------------------------------------------- maps */
typedef struct band_progress {
    sk_progress_bar *bar;
    double base, span;
} band_progress;

static void band_progress_fn(void *user, double fraction)
{
    band_progress *b = user;
    sk_progress_bar_update(b->bar, b->base + b->span * fraction);
}

/* A colour per cell id (stable for a seed): for per-ridge variation in shaders. */
static void id_colour(uint32_t id, float rgb[3])
{
    uint64_t h = sk_hash(0x43454c4cULL, id, 0, 0);
    for (int i = 0; i < 3; i++) rgb[i] = (float)((h >> (16 * i)) & 0xffff) / 65535.0f;
}

typedef struct map_images {
    sk_image height, normal, furrow, cells, preview, edges;
} map_images;

/* One file to write: PNG (with its desc) or EXR. */
typedef struct map_file {
    const sk_image *image;
    char path[4096];
    bool exr;
    sk_exr_compression exr_compression;
    sk_png_write_desc png;
    sk_image_metadata meta;
} map_file;

/* Converts the rendered maps to their file encodings and writes the files, several at a
 * time (each compression runs on its own thread). Converts m in place. */
static sk_result write_maps(const sk_skin *skin, map_images *m, const char *dir, int w, int h,
                            bool directx, bool edges, int furrow_level, float furrow_max,
                            sk_error *err)
{
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    sk_image_metadata meta = {0};
    describe(skin, w, h, &meta);
    char v[160];
    sk_image scaled = {0};
    sk_result r = sk_image_create(&scaled, m->height.width, m->height.height, 1, err);
    if (r != SK_OK) return r;
    size_t n = (size_t)m->height.width * (size_t)m->height.height;
#pragma omp parallel for schedule(static)
    for (long j = 0; j < (long)n; j++) {
        size_t i = (size_t)j;
        /* height: 16-bit PNG over the skin's height range (the EXR keeps mm) */
        scaled.data[i] = (m->height.data[i] - lo) / (hi - lo);
        /* furrow distance, 16-bit over [0, furrow_max] */
        float d = m->furrow.data[i] / furrow_max;
        m->furrow.data[i] = d > 1.0f ? 1.0f : d;
        /* tangent-space normals, 8-bit: OpenGL (green up) or DirectX (green down) */
        float *p = m->normal.data + 3 * i;
        if (directx) p[1] = -p[1];
        for (int c = 0; c < 3; c++) p[c] = 0.5f * p[c] + 0.5f;
    }

    map_file files[7];
    int count = 0;
    /* Big maps spend most of their time in zlib: level 2 writes a 4096 x 4096 set about
       three times faster than the default 6, for files 2-20 % larger; the float height
       (noise to zlib) is stored uncompressed, 6 % larger and 40 times faster. */
    bool fast = n >= SKIN_FAST_PNG_PIXELS;
    int level = fast ? 2 : 0;
    sk_png_write_desc png16 = {.bit_depth = 16, .encoding = SK_PNG_ENCODING_LINEAR,
                               .compression_level = level};
    sk_png_write_desc png8 = {.bit_depth = 8, .encoding = SK_PNG_ENCODING_LINEAR,
                              .compression_level = level};
    sk_png_write_desc srgb = {.bit_depth = 8, .encoding = SK_PNG_ENCODING_SRGB,
                              .compression_level = level};
    map_file *f;

    f = &files[count++];
    *f = (map_file){.image = &m->height, .exr = true, .meta = meta,
                    .exr_compression = fast ? SK_EXR_COMPRESSION_NONE : SK_EXR_COMPRESSION_DEFAULT};
    snprintf(f->path, sizeof f->path, "%s/height.exr", dir);
    sk_image_metadata_set(&f->meta, "shitsukan:units", "mm", NULL);
    snprintf(v, sizeof v, "%.9g", lo);
    sk_image_metadata_set(&f->meta, "shitsukan:height_min_mm", v, NULL);
    snprintf(v, sizeof v, "%.9g", hi);
    sk_image_metadata_set(&f->meta, "shitsukan:height_max_mm", v, NULL);

    /* then the slowest encodings first, so the threads finish together */
    f = &files[count++];
    *f = (map_file){.image = &m->preview, .png = srgb, .meta = meta};
    snprintf(f->path, sizeof f->path, "%s/preview.png", dir);

    if (edges) {
        f = &files[count++];
        *f = (map_file){.image = &m->edges, .png = srgb, .meta = meta};
        snprintf(f->path, sizeof f->path, "%s/edges.png", dir);
    }

    f = &files[count++];
    *f = (map_file){.image = &m->normal, .png = png8, .meta = meta};
    snprintf(f->path, sizeof f->path, "%s/normal.png", dir);
    sk_image_metadata_set(&f->meta, "shitsukan:normal_convention", directx ? "directx" : "opengl",
                          NULL);

    f = &files[count++];
    *f = (map_file){.image = &scaled, .png = png16, .meta = files[0].meta};
    snprintf(f->path, sizeof f->path, "%s/height.png", dir);
    snprintf(v, sizeof v, "height_mm = %.9g + value * %.9g (value = code / 65535)", lo, hi - lo);
    sk_image_metadata_set(&f->meta, "shitsukan:decode", v, NULL);

    f = &files[count++];
    *f = (map_file){.image = &m->furrow, .png = png16, .meta = meta};
    snprintf(f->path, sizeof f->path, "%s/furrow.png", dir);
    snprintf(v, sizeof v, "%d", furrow_level);
    sk_image_metadata_set(&f->meta, "shitsukan:furrow_level", v, NULL);
    snprintf(v, sizeof v, "distance_mm = value * %.9g (clamped there)", furrow_max);
    sk_image_metadata_set(&f->meta, "shitsukan:decode", v, NULL);

    f = &files[count++];
    *f = (map_file){.image = &m->cells, .png = png8, .meta = meta};
    snprintf(f->path, sizeof f->path, "%s/cells.png", dir);

    sk_result results[7];
    sk_error errors[7];
#pragma omp parallel for schedule(dynamic, 1)
    for (int i = 0; i < count; i++) {
        map_file *mf = &files[i];
        sk_error_clear(&errors[i]);
        if (mf->exr) {
            sk_exr_write_desc exr = {.metadata = &mf->meta, .compression = mf->exr_compression};
            results[i] = sk_image_write_exr(mf->image, mf->path, &exr, &errors[i]);
        } else {
            mf->png.metadata = &mf->meta;
            results[i] = sk_image_write_png(mf->image, mf->path, &mf->png, &errors[i]);
        }
    }
    sk_image_free(&scaled);
    for (int i = 0; i < count; i++)
        if (results[i] != SK_OK) {
            if (err) *err = errors[i];
            return results[i];
        }
    return SK_OK;
}

static int run_maps(const cli_command *command, const cli_args *args)
{
    const char *dir = args->common.output;
    if (!dir) return cli_fail(CLI_EXIT_USAGE, "skin maps: -o/--output DIR is required");
    sk_skin_desc desc;
    int w, h, region[4], status;
    long long samples, furrow_level, id_level;
    if ((status = load_desc(command, args, 1024, &desc, &w, &h))) return status;
    if ((status = get_region(command, args, w, h, region))) return status;
    if ((status = cli_get_int(command, args, "samples", 1, 1, 8, &samples))) return status;
    if ((status =
             cli_get_int(command, args, "furrow-level", 1, 1, SK_SKIN_MAX_LEVELS, &furrow_level)))
        return status;
    if ((status = cli_get_int(command, args, "id-level", 1, 1, SK_SKIN_MAX_LEVELS, &id_level)))
        return status;
    bool edges = cli_has(command, args, "edges"), directx = cli_has(command, args, "directx");
    /* All maps are held in memory until written (float maps, the scaled height and the
       encodings being written): split a huge map with --region. */
    if ((status = check_image_memory(args, region[2], region[3], 4.0 * (edges ? 15 : 12) + 16,
                                     &desc)))
        return status;
    /* the folder is reserved first: its files appear together at the end, or none */
    sk_error err = {0};
    sk_output_set *outputs = NULL;
    const char *staged = NULL;
    if (sk_output_set_create(&outputs, &err) != SK_OK ||
        sk_output_set_folder(outputs, dir, &staged, &err) != SK_OK) {
        sk_output_set_abort(outputs);
        return cli_fail_error(&err);
    }
    sk_skin *skin;
    if ((status = make_skin(&desc, args, &skin))) {
        sk_output_set_abort(outputs);
        return status;
    }
    const sk_skin_desc *rd_desc = sk_skin_get_desc(skin);
    sk_result r = SK_OK;
    int level_count = rd_desc->level_count;
    if (furrow_level > level_count || id_level > level_count) {
        sk_skin_destroy(skin);
        sk_output_set_abort(outputs);
        return cli_fail(CLI_EXIT_USAGE,
                        "--furrow-level and --id-level must be at most %d (the "
                        "skin's levels)",
                        level_count);
    }
    map_images m;
    memset(&m, 0, sizeof m);
    uint32_t *ids = malloc(sizeof(uint32_t) * (size_t)region[2] * SKIN_BAND_ROWS);
    if (!ids) r = sk_fail(&err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    int rw = region[2], rh = region[3];
    if (r == SK_OK) r = sk_image_create(&m.height, rw, rh, 1, &err);
    if (r == SK_OK) r = sk_image_create(&m.normal, rw, rh, 3, &err);
    if (r == SK_OK) r = sk_image_create(&m.furrow, rw, rh, 1, &err);
    if (r == SK_OK) r = sk_image_create(&m.cells, rw, rh, 3, &err);
    if (r == SK_OK) r = sk_image_create(&m.preview, rw, rh, 3, &err);
    if (r == SK_OK && edges) r = sk_image_create(&m.edges, rw, rh, 3, &err);
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "skin maps", !args->common.quiet);
    for (int y0 = 0; r == SK_OK && y0 < rh; y0 += SKIN_BAND_ROWS) {
        int rows = rh - y0 < SKIN_BAND_ROWS ? rh - y0 : SKIN_BAND_ROWS;
        size_t off = (size_t)y0 * (size_t)rw;
        band_progress bp = {&bar, (double)y0 / rh, (double)rows / rh};
        sk_skin_render_desc rd = {
            .width = w,
            .height = h,
            .region = {region[0], region[1] + y0, rw, rows},
            .height_mm = m.height.data + off,
            .normal = m.normal.data + 3 * off,
            .furrow = m.furrow.data + off,
            .cell_id = ids,
            .preview = m.preview.data + 3 * off,
            .edges = edges ? m.edges.data + 3 * off : NULL,
            .furrow_level = (int)furrow_level,
            .id_level = (int)id_level,
            .samples = (int)samples,
            .progress = {band_progress_fn, &bp},
        };
        r = sk_skin_render(skin, &rd, &err);
        if (r != SK_OK) break;
        long band = (long)rows * rw;
#pragma omp parallel for schedule(static)
        for (long i = 0; i < band; i++) id_colour(ids[i], m.cells.data + 3 * (off + (size_t)i));
    }
    sk_progress_bar_end(&bar);
    /* furrow.png spans half the furrow level's spacing: the whole ridge, centre to edge */
    float furrow_max = 0.5f * rd_desc->levels[furrow_level - 1].spacing_mm;
    if (r == SK_OK)
        r = write_maps(skin, &m, staged, w, h, directx, edges, (int)furrow_level, furrow_max,
                       &err);
    if (r == SK_OK) r = sk_output_set_commit(outputs, &err);
    else sk_output_set_abort(outputs);
    if (r == SK_OK && !args->common.quiet) {
        float lo, hi;
        double tw, th;
        sk_skin_height_range(skin, &lo, &hi);
        sk_skin_tile_size(skin, &tw, &th);
        printf("%s: height.png/.exr, normal.png (%s), furrow.png, cells.png, preview.png%s\n", dir,
               directx ? "DirectX" : "OpenGL", edges ? ", edges.png" : "");
        printf("tile %.6g x %.6g mm, %.6g mm per pixel%s\n", tw, th, tw / w,
               rd_desc->aperiodic ? "" : ", seamless");
        printf("height.png: 0 = %.6g mm, 65535 = %.6g mm (height.exr holds mm)\n", lo, hi);
        printf("furrow.png: 0 = on a level-%lld furrow, 65535 = %.6g mm or more from one\n",
               furrow_level, furrow_max);
    }
    free(ids);
    sk_image_free(&m.height);
    sk_image_free(&m.normal);
    sk_image_free(&m.furrow);
    sk_image_free(&m.cells);
    sk_image_free(&m.preview);
    sk_image_free(&m.edges);
    sk_skin_destroy(skin);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

const cli_command cmd_skin = {
    .name = "skin",
    .summary = "skin microrelief (Ishii et al. 1991): shaded preview as in the paper",
    .usage = "shitsukan skin [options] -o OUT.png",
    .description =
        "Builds the skin surface of Ishii, Yasuda, Yokoi and Toriwaki (1991): ridges as\n"
        "hierarchical Voronoi polygons with perturbed furrows, stretched along a direction,\n"
        "each with a Bezier section profile, and shades it by bump mapping under a\n"
        "directional light (Lambert plus a soft highlight, skin-tone albedo). Every row of\n"
        "the paper's Table 1 is a preset (fig13a ... fig19f); real regions too\n"
        "(back-of-hand, wrist, forearm). 'shitsukan presets skin' lists them and\n"
        "'--help-keys' the parameters.",
    .examples = "  shitsukan skin --preset fig19a -o fig19a.png\n"
                "  shitsukan skin --preset fig14c --set levels[0].roundness=0.6 -o round.png\n"
                "  shitsukan skin --preset back-of-hand --size 800 --samples 2 -o hand.png",
    .options = k_preview_options,
    .option_count = (int)(sizeof k_preview_options / sizeof k_preview_options[0]),
    .common = CLI_COMMON_ALL,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "skin",
    .schema = &sk_skin_schema,
    .run = run_preview,
};

const cli_command cmd_skin_maps = {
    .name = "skin maps",
    .summary = "skin microrelief maps: height (PNG 16-bit, EXR), normal, furrow, cells, preview",
    .usage = "shitsukan skin maps [options] -o DIR",
    .description =
        "Writes the maps a renderer takes into DIR: height.exr (mm) and height.png (16-bit,\n"
        "its mm range in the file's metadata and printed), normal.png (tangent space,\n"
        "OpenGL convention, --directx for green down), furrow.png (distance to the nearest\n"
        "furrow), cells.png (a colour per ridge) and preview.png; --edges adds edges.png.\n"
        "Maps tile seamlessly unless the preset sets \"aperiodic\": true. --region renders\n"
        "a part with exactly the pixels of the whole map, so a huge map can be split.",
    .examples = "  shitsukan skin maps --preset back-of-hand --size 4096 -o hand-maps\n"
                "  shitsukan skin maps --preset wrist --size 8192 --region 0,0,4096,4096 -o part",
    .options = k_maps_options,
    .option_count = (int)(sizeof k_maps_options / sizeof k_maps_options[0]),
    .common = CLI_COMMON_ALL,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "skin",
    .schema = &sk_skin_schema,
    .run = run_maps,
};
