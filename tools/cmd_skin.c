/* `shitsukan skin` (shaded preview, as the paper's figures) and `shitsukan skin maps`
 * (height, normal, furrow, cell and preview maps for renderers) of the skin microrelief
 * model of Ishii et al. 1991. Parses arguments, loads presets, calls the library, writes
 * files. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "shitsukan/io.h"
#include "shitsukan/maps.h"
#include "shitsukan/skin.h"

#define SKIN_DEFAULT_SIZE 400
/* Maps of at least this many pixels are written with a fast deflate level. */
#define SKIN_FAST_PNG_PIXELS (2048 * 2048)

/* The files' Software key. */
static const char k_software[] = "shitsukan " SK_VERSION_STRING;

static const cli_option k_preview_options[] = {
    {"size", 0, "N|WxH",
     "image size in pixels; default 400 (the paper's) on the tile's shorter side", false},
    {"mm-per-px", 0, "MM", "pixel size in mm (the tile becomes size x MM); default from size_mm",
     false},
    {"region", 0, "x,y,w,h", "render only this sub-rectangle (same pixels as the full image)",
     false},
    {"samples", 0, "N", "samples per pixel side (anti-aliasing), 1..8; default 1", false},
    {"edges", 0, NULL, "draw each level's furrows in colour over the shading", false},
};

static const cli_option k_maps_options[] = {
    {"size", 0, "N|WxH", "map size in pixels; default 1024 on the tile's shorter side", false},
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
    /* the default keeps the tile's shape: default_size pixels on its shorter side */
    sk_skin_desc resolved = sk_skin_desc_resolved(desc);
    double aspect = (double)resolved.size_mm[0] / resolved.size_mm[1];
    double dw = aspect > 1 ? default_size * aspect : default_size;
    double dh = aspect < 1 ? default_size / aspect : default_size;
    if (!(dw <= SK_IMAGE_MAX_DIMENSION)) dw = SK_IMAGE_MAX_DIMENSION;
    if (!(dh <= SK_IMAGE_MAX_DIMENSION)) dh = SK_IMAGE_MAX_DIMENSION;
    if ((status = cli_get_size(command, args, "size", (int)lround(dw), (int)lround(dh),
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

/* Where the time of a command goes, printed on stderr when SHITSUKAN_TIMINGS is set (the
 * benchmarks read it): building the cells (model), rendering (shading) and the files, in
 * wall time and in the CPU time of all threads (which a loaded machine inflates less). */
typedef struct phase_mark {
    double wall, cpu;
} phase_mark;

typedef struct phase_times {
    phase_mark start, model, shading, files;
} phase_times;

static phase_mark phase_now(void)
{
    return (phase_mark){sk_time_seconds(), (double)clock() / CLOCKS_PER_SEC};
}

static void phase_report(const char *name, const phase_times *t)
{
    if (!getenv("SHITSUKAN_TIMINGS")) return;
    fprintf(stderr,
            "%s timings: model %.1f ms, shading %.1f ms, files %.1f ms (CPU %.1f, %.1f, %.1f ms)\n",
            name, (t->model.wall - t->start.wall) * 1e3, (t->shading.wall - t->model.wall) * 1e3,
            (t->files.wall - t->shading.wall) * 1e3, (t->model.cpu - t->start.cpu) * 1e3,
            (t->shading.cpu - t->model.cpu) * 1e3, (t->files.cpu - t->shading.cpu) * 1e3);
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
    phase_times times = {.start = phase_now()};
    sk_skin *skin;
    if ((status = make_skin(&desc, args, &skin))) return status;
    times.model = phase_now();
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
    times.shading = phase_now();
    sk_threads_rest(); /* one thread writes the file */
    if (r == SK_OK) {
        sk_image_metadata meta = {0};
        sk_skin_image_metadata(skin, w, k_software, &meta, NULL);
        /* deflate level 2: a shaded preview comes out about as small as at the default 6,
           in half the time */
        sk_png_write_desc png = {.bit_depth = 8,
                                 .encoding = SK_PNG_ENCODING_SRGB,
                                 .metadata = &meta,
                                 .compression_level = 2};
        r = sk_image_write_png(&image, output, &png, &err);
    }
    times.files = phase_now();
    sk_image_free(&image);
    sk_skin_destroy(skin);
    if (r == SK_OK) phase_report("skin", &times);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

/* --------------------------------------------------------------------- maps */
/* One map of the set, row by row as the PNG writer asks (no float copy of a whole map is
 * made). */
typedef struct map_rows {
    const sk_skin_maps *maps;
    sk_skin_map map;
} map_rows;

static void map_row(void *user, int y, float *row)
{
    const map_rows *r = user;
    sk_skin_maps_rows(r->maps, r->map, y, 1, row, NULL);
}

/* Writes the files of the set one after another (each on every thread), freeing what each
 * leaves unused (sk_skin_maps_release). */
static sk_result write_maps(sk_skin_maps *maps, const char *dir, sk_error *err)
{
    const sk_skin_maps_desc *d = sk_skin_maps_get_desc(maps);
    /* Big maps spend most of their time in deflate: level 1 writes a 4096 x 4096 set in
       about half the time of the default 6, for files 0-12 % larger (docs/skin.md); the
       float height (noise to deflate) is stored uncompressed, 6 % larger and 40 times
       faster. */
    bool fast = (size_t)d->region[2] * (size_t)d->region[3] >= SKIN_FAST_PNG_PIXELS;
    for (int k = 0; k < SK_SKIN_MAP_COUNT; k++) {
        sk_skin_map map = (sk_skin_map)k;
        if (!sk_skin_maps_holds(maps, map)) continue;
        const sk_map_info *info = sk_skin_map_info(map);
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, info->file);
        sk_image_metadata meta = {0};
        sk_result r = sk_skin_maps_metadata(maps, map, k_software, &meta, err);
        const sk_image *image = sk_skin_maps_image(maps, map);
        if (r == SK_OK && info->bit_depth == 32) {
            sk_exr_write_desc exr = {.metadata = &meta,
                                     .compression = fast ? SK_EXR_COMPRESSION_NONE
                                                         : SK_EXR_COMPRESSION_DEFAULT};
            r = sk_image_write_exr(image, path, &exr, err);
        } else if (r == SK_OK) {
            sk_png_write_desc png = {.bit_depth = info->bit_depth,
                                     .encoding =
                                         info->srgb ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR,
                                     .metadata = &meta,
                                     .compression_level = fast ? 1 : 0};
            map_rows rows = {maps, map};
            sk_image_rows source = {.width = d->region[2],
                                    .height = d->region[3],
                                    .channels = info->channels,
                                    .get_row = map_row,
                                    .user = &rows};
            r = image ? sk_image_write_png(image, path, &png, err)
                      : sk_image_write_png_rows(&source, path, &png, err);
        }
        if (r != SK_OK) return r;
        sk_skin_maps_release(maps, map);
    }
    return SK_OK;
}

/* The set's options from the command line. */
static int get_maps_desc(const cli_command *command, const cli_args *args, int w, int h,
                         const int region[4], sk_skin_maps_desc *md)
{
    long long samples, furrow_level, id_level;
    int status;
    if ((status = cli_get_int(command, args, "samples", 1, 1, 8, &samples))) return status;
    if ((status =
             cli_get_int(command, args, "furrow-level", 1, 1, SK_SKIN_MAX_LEVELS, &furrow_level)))
        return status;
    if ((status = cli_get_int(command, args, "id-level", 1, 1, SK_SKIN_MAX_LEVELS, &id_level)))
        return status;
    *md = (sk_skin_maps_desc){
        .width = w,
        .height = h,
        .region = {region[0], region[1], region[2], region[3]},
        .maps = SK_SKIN_MAPS_DEFAULT |
                (cli_has(command, args, "edges") ? SK_SKIN_MAP_BIT(SK_SKIN_MAP_EDGES) : 0u),
        .furrow_level = (int)furrow_level,
        .id_level = (int)id_level,
        .samples = (int)samples,
        .directx = cli_has(command, args, "directx"),
    };
    return 0;
}

/* What the command prints of a written set. */
static void print_maps(const sk_skin *skin, const sk_skin_maps_desc *md, const char *dir)
{
    float lo, hi;
    double tw, th;
    sk_skin_height_range(skin, &lo, &hi);
    sk_skin_tile_size(skin, &tw, &th);
    bool edges = md->maps & SK_SKIN_MAP_BIT(SK_SKIN_MAP_EDGES);
    printf("%s: height.png/.exr, normal.png (%s), furrow.png, cells.png, preview.png%s\n", dir,
           md->directx ? "DirectX" : "OpenGL", edges ? ", edges.png" : "");
    printf("tile %.6g x %.6g mm, %.6g mm per pixel%s\n", tw, th, tw / md->width,
           sk_skin_get_desc(skin)->aperiodic ? "" : ", seamless");
    printf("height.png: 0 = %.6g mm, 65535 = %.6g mm (height.exr holds mm)\n", lo, hi);
    printf("furrow.png: 0 = on a level-%d furrow, 65535 = %.6g mm or more from one\n",
           md->furrow_level, sk_skin_maps_furrow_span(skin, md->furrow_level));
}

static int run_maps(const cli_command *command, const cli_args *args)
{
    const char *dir = args->common.output;
    if (!dir) return cli_fail(CLI_EXIT_USAGE, "skin maps: -o/--output DIR is required");
    sk_skin_desc desc;
    sk_skin_maps_desc md;
    int w, h, region[4], status;
    if ((status = load_desc(command, args, 1024, &desc, &w, &h))) return status;
    if ((status = get_region(command, args, w, h, region))) return status;
    if ((status = get_maps_desc(command, args, w, h, region, &md))) return status;
    /* All maps are held in memory until written (the maps as stored and the encodings
       being written): split a huge map with --region. */
    double per_px = sk_skin_maps_bytes_per_pixel(&md);
    if ((status = check_image_memory(args, region[2], region[3], per_px + 16, &desc)))
        return status;
    phase_times times = {.start = phase_now()};
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
    times.model = phase_now();
    int level_count = sk_skin_get_desc(skin)->level_count;
    if (md.furrow_level > level_count || md.id_level > level_count) {
        sk_skin_destroy(skin);
        sk_output_set_abort(outputs);
        return cli_fail(CLI_EXIT_USAGE,
                        "--furrow-level and --id-level must be at most %d (the "
                        "skin's levels)",
                        level_count);
    }
    sk_progress_bar bar;
    md.progress = sk_progress_bar_sink(&bar);
    sk_skin_maps *maps = NULL;
    sk_result r = sk_skin_maps_create(&maps, skin, &md, &err);
    sk_progress_bar_begin(&bar, "skin maps", !args->common.quiet);
    if (r == SK_OK) r = sk_skin_maps_render(maps, 0, &err);
    sk_progress_bar_end(&bar);
    times.shading = phase_now();
    if (r == SK_OK) r = write_maps(maps, staged, &err);
    if (r == SK_OK)
        r = sk_output_set_commit(outputs, &err);
    else
        sk_output_set_abort(outputs);
    times.files = phase_now();
    if (r == SK_OK && !args->common.quiet) print_maps(skin, &md, dir);
    sk_skin_maps_destroy(maps);
    sk_skin_destroy(skin);
    if (r == SK_OK) phase_report("skin maps", &times);
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
