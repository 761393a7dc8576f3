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
#include "shitsukan/skin.h"

#define SKIN_DEFAULT_SIZE 400
/* Rows of a band of the maps a thread renders at a time. */
#define SKIN_BAND_ROWS 4
/* Maps of fewer pixel-levels (pixels x levels x samples^2) render on one thread, as the
   renderer's own loop does: starting a second costs more than it saves. */
#define SKIN_PARALLEL_WORK 32768
/* Maps of at least this many pixels are written with a fast deflate level. */
#define SKIN_FAST_PNG_PIXELS (2048 * 2048)

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
    sk_image_metadata_set(meta, SK_IMAGE_KEY_MM_PER_PIXEL, v, NULL);
    sk_image_metadata_set(meta, "shitsukan:seamless", d->aperiodic ? "false" : "true", NULL);
    sk_image_metadata_set(meta, "Software", "shitsukan " SK_VERSION_STRING, NULL);
    (void)h;
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
        describe(skin, w, h, &meta);
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
/* A colour per cell id (stable for a seed): for per-ridge variation in shaders. */
static void id_colour(uint32_t id, float rgb[3]) { sk_skin_cell_color(id, rgb); }

/* What a map set keeps of every pixel between rendering and writing: height in mm (float,
 * height.exr), the normal's x and y in 1/32767 (z follows; normal.png and the preview
 * come from it, within one code of the float normal's in about 0.1 % of the samples),
 * the furrow distance as furrow.png's 16-bit code and the cell id: 14 bytes a pixel
 * instead of the 44 of float maps. With --samples > 1 the preview, and with --edges the
 * overlay, are rendered and kept as float images. */
typedef struct map_store {
    int w, h;
    size_t n;
    sk_image height;
    int16_t *normal;
    uint16_t *furrow;
    uint32_t *ids;
    sk_image preview, edges; /* only when rendered */
} map_store;

static void map_store_free(map_store *m)
{
    sk_image_free(&m->height);
    free(m->normal), m->normal = NULL;
    free(m->furrow), m->furrow = NULL;
    free(m->ids), m->ids = NULL;
    sk_image_free(&m->preview);
    sk_image_free(&m->edges);
}

static void stored_normal(const map_store *m, size_t i, float n[3])
{
    n[0] = m->normal[2 * i] / 32767.0f, n[1] = m->normal[2 * i + 1] / 32767.0f;
    float zz = 1.0f - n[0] * n[0] - n[1] * n[1];
    n[2] = zz > 0.0f ? sqrtf(zz) : 0.0f;
}

/* One file: where it goes, how it is encoded and its metadata. */
typedef struct map_file {
    char path[4096];
    sk_png_write_desc png;
    sk_image_metadata meta;
} map_file;

static sk_result write_png_file(const sk_image *image, map_file *f, sk_error *err)
{
    f->png.metadata = &f->meta;
    return sk_image_write_png(image, f->path, &f->png, err);
}

/* The files made from the store, row by row as the writer asks (no float copy of a whole
 * map is made). */
enum { MAP_HEIGHT, MAP_FURROW, MAP_CELLS, MAP_NORMAL, MAP_PREVIEW };

typedef struct map_rows {
    const sk_skin *skin;
    const map_store *m;
    int which;
    bool directx;
    float lo, span; /* height.png: value = (height - lo) / span */
} map_rows;

static void map_row(void *user, int y, float *row)
{
    const map_rows *r = user;
    const map_store *m = r->m;
    size_t i0 = (size_t)y * (size_t)m->w;
    for (int x = 0; x < m->w; x++) {
        size_t i = i0 + (size_t)x;
        if (r->which == MAP_HEIGHT) {
            row[x] = (m->height.data[i] - r->lo) / r->span;
            continue;
        }
        if (r->which == MAP_FURROW) {
            row[x] = m->furrow[i] / 65535.0f;
            continue;
        }
        float *p = row + 3 * x;
        if (r->which == MAP_CELLS) {
            id_colour(m->ids[i], p);
            continue;
        }
        float nv[3];
        stored_normal(m, i, nv);
        if (r->which == MAP_NORMAL) {
            /* tangent-space normals, 8-bit: OpenGL (green up) or DirectX (green down) */
            if (r->directx) nv[1] = -nv[1];
            for (int c = 0; c < 3; c++) p[c] = 0.5f * nv[c] + 0.5f;
        } else {
            sk_vec3f c = sk_skin_shade(r->skin, sk_v3f(nv[0], nv[1], nv[2]));
            p[0] = c.x, p[1] = c.y, p[2] = c.z;
        }
    }
}

static sk_result write_map_rows(map_rows *r, map_file *f, sk_error *err)
{
    sk_image_rows rows = {.width = r->m->w,
                          .height = r->m->h,
                          .channels = r->which == MAP_HEIGHT || r->which == MAP_FURROW ? 1 : 3,
                          .get_row = map_row,
                          .user = r};
    f->png.metadata = &f->meta;
    return sk_image_write_png_rows(&rows, f->path, &f->png, err);
}

/* Writes the files one after another (each on every thread), freeing what each leaves
 * unused: height.exr, height.png, furrow.png, then the 3-channel files. */
static sk_result write_maps(const sk_skin *skin, map_store *m, const char *dir, int w, int h,
                            bool directx, bool edges, int furrow_level, float furrow_max,
                            sk_error *err)
{
    float lo, hi;
    sk_skin_height_range(skin, &lo, &hi);
    sk_image_metadata meta = {0};
    describe(skin, w, h, &meta);
    char v[160];
    /* Big maps spend most of their time in deflate: level 1 writes a 4096 x 4096 set in
       about half the time of the default 6, for files 0-12 % larger (docs/skin.md); the
       float height (noise to deflate) is stored uncompressed, 6 % larger and 40 times
       faster. */
    bool fast = m->n >= SKIN_FAST_PNG_PIXELS;
    int level = fast ? 1 : 0;
    sk_png_write_desc png16 = {
        .bit_depth = 16, .encoding = SK_PNG_ENCODING_LINEAR, .compression_level = level};
    sk_png_write_desc png8 = {
        .bit_depth = 8, .encoding = SK_PNG_ENCODING_LINEAR, .compression_level = level};
    sk_png_write_desc srgb = {
        .bit_depth = 8, .encoding = SK_PNG_ENCODING_SRGB, .compression_level = level};

    sk_image_metadata height_meta = meta;
    sk_image_metadata_set(&height_meta, "shitsukan:units", "mm", NULL);
    snprintf(v, sizeof v, "%.9g", lo);
    sk_image_metadata_set(&height_meta, "shitsukan:height_min_mm", v, NULL);
    snprintf(v, sizeof v, "%.9g", hi);
    sk_image_metadata_set(&height_meta, "shitsukan:height_max_mm", v, NULL);
    char path[4096];
    snprintf(path, sizeof path, "%s/height.exr", dir);
    sk_exr_write_desc exr = {.metadata = &height_meta,
                             .compression =
                                 fast ? SK_EXR_COMPRESSION_NONE : SK_EXR_COMPRESSION_DEFAULT};
    sk_result r = sk_image_write_exr(&m->height, path, &exr, err);
    if (r != SK_OK) return r;

    /* height.png: 16-bit over the skin's height range (the EXR keeps mm) */
    map_file f = {.png = png16, .meta = height_meta};
    snprintf(f.path, sizeof f.path, "%s/height.png", dir);
    snprintf(v, sizeof v, "height_mm = %.9g + value * %.9g (value = code / 65535)", lo, hi - lo);
    sk_image_metadata_set(&f.meta, "shitsukan:decode", v, NULL);
    map_rows rows = {
        .skin = skin, .m = m, .which = MAP_HEIGHT, .directx = directx, .lo = lo, .span = hi - lo};
    if ((r = write_map_rows(&rows, &f, err)) != SK_OK) return r;
    sk_image_free(&m->height);

    f = (map_file){.png = png16, .meta = meta};
    snprintf(f.path, sizeof f.path, "%s/furrow.png", dir);
    snprintf(v, sizeof v, "%d", furrow_level);
    sk_image_metadata_set(&f.meta, "shitsukan:furrow_level", v, NULL);
    snprintf(v, sizeof v, "distance_mm = value * %.9g (clamped there)", furrow_max);
    sk_image_metadata_set(&f.meta, "shitsukan:decode", v, NULL);
    rows.which = MAP_FURROW;
    if ((r = write_map_rows(&rows, &f, err)) != SK_OK) return r;
    free(m->furrow), m->furrow = NULL;

    const char *names[3] = {"cells.png", "normal.png", "preview.png"};
    for (int which = MAP_CELLS; which <= MAP_PREVIEW; which++) {
        f = (map_file){.png = which == MAP_PREVIEW ? srgb : png8, .meta = meta};
        snprintf(f.path, sizeof f.path, "%s/%s", dir, names[which - MAP_CELLS]);
        if (which == MAP_NORMAL)
            sk_image_metadata_set(&f.meta, "shitsukan:normal_convention",
                                  directx ? "directx" : "opengl", NULL);
        rows.which = which;
        r = which == MAP_PREVIEW && m->preview.data ? write_png_file(&m->preview, &f, err)
                                                    : write_map_rows(&rows, &f, err);
        if (r != SK_OK) return r;
        if (which == MAP_CELLS) free(m->ids), m->ids = NULL;
    }
    if (!edges) return SK_OK;
    f = (map_file){.png = srgb, .meta = meta};
    snprintf(f.path, sizeof f.path, "%s/edges.png", dir);
    return write_png_file(&m->edges, &f, err);
}

/* What every band of the maps shares. */
typedef struct band_job {
    const sk_skin *skin;
    map_store *m;
    int w, h, region[4], furrow_level, id_level, samples;
    bool edges;
    float furrow_max;
} band_job;

/* Renders band b (rows from b * SKIN_BAND_ROWS) into the store, through the thread's own
 * normal and furrow buffers (the height goes straight into the store). */
static sk_result render_band(const band_job *job, int b, float *normal, float *furrow,
                             sk_error *err)
{
    map_store *m = job->m;
    int rw = job->region[2], y0 = b * SKIN_BAND_ROWS;
    int rows = job->region[3] - y0 < SKIN_BAND_ROWS ? job->region[3] - y0 : SKIN_BAND_ROWS;
    size_t off = (size_t)y0 * (size_t)rw;
    sk_skin_render_desc rd = {
        .width = job->w,
        .height = job->h,
        .region = {job->region[0], job->region[1] + y0, rw, rows},
        .height_mm = m->height.data + off,
        .normal = normal,
        .furrow = furrow,
        .cell_id = m->ids + off,
        .preview = m->preview.data ? m->preview.data + 3 * off : NULL,
        .edges = job->edges ? m->edges.data + 3 * off : NULL,
        .furrow_level = job->furrow_level,
        .id_level = job->id_level,
        .samples = job->samples,
    };
    sk_result r = sk_skin_render(job->skin, &rd, err);
    if (r != SK_OK) return r;
    for (size_t i = 0; i < (size_t)rows * (size_t)rw; i++) {
        size_t o = off + i;
        for (int c = 0; c < 2; c++)
            m->normal[2 * o + c] = (int16_t)lrintf(normal[3 * i + c] * 32767.0f);
        /* furrow.png's code: the distance over [0, furrow_max] */
        float d = furrow[i] / job->furrow_max;
        m->furrow[o] = (uint16_t)lrint((d > 1.0f ? 1.0f : d) * 65535.0);
    }
    return SK_OK;
}

/* Renders the region into the store in bands of a few rows, shared out between the
 * threads in one parallel loop: each thread renders a band on its own (the renderer's
 * loop inside runs on that thread) and stores it at once, so threads wait for one another
 * only at the end. Maps of little work run on one thread. */
static sk_result render_maps(const band_job *job, sk_progress_bar *bar, sk_error *err)
{
    int rh = job->region[3], bands = (rh + SKIN_BAND_ROWS - 1) / SKIN_BAND_ROWS;
    double work = (double)job->region[2] * rh * sk_skin_get_desc(job->skin)->level_count *
                  job->samples * job->samples;
    sk_result result = SK_OK;
    bool failed = false;
    long rows_done = 0;
#pragma omp parallel if (work >= SKIN_PARALLEL_WORK && bands > 1)
    {
        size_t band_px = (size_t)job->region[2] * SKIN_BAND_ROWS;
        float *normal = malloc(sizeof(float) * 3 * band_px),
              *furrow = malloc(sizeof(float) * band_px);
#pragma omp for schedule(dynamic, 1)
        for (int b = 0; b < bands; b++) {
            bool stop;
#pragma omp atomic read
            stop = failed;
            if (stop) continue;
            sk_error band_err = {0};
            sk_result r = normal && furrow ? render_band(job, b, normal, furrow, &band_err)
                                           : sk_fail(&band_err, SK_ERROR_OUT_OF_MEMORY,
                                                     "out of memory for a band of the maps");
#pragma omp critical(skin_maps_progress)
            {
                if (r != SK_OK && !failed) { /* the first failure is reported */
                    result = r;
                    if (err) *err = band_err;
#pragma omp atomic write
                    failed = true;
                }
                rows_done += r == SK_OK ? SKIN_BAND_ROWS : 0;
                if (r == SK_OK)
                    sk_progress_bar_update(bar, (double)(rows_done < rh ? rows_done : rh) / rh);
            }
        }
        free(normal), free(furrow);
    }
    return result;
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
    /* All maps are held in memory until written (the maps as stored and the encodings
       being written): split a huge map with --region. */
    bool own_preview = samples > 1; /* else shaded from the kept normals */
    double per_px = 14 + 12.0 * own_preview + 12.0 * edges;
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
    int rw = region[2], rh = region[3];
    map_store m = {.w = rw, .h = rh, .n = (size_t)rw * (size_t)rh};
    r = sk_image_create(&m.height, rw, rh, 1, &err);
    if (r == SK_OK) {
        m.normal = malloc(sizeof(int16_t) * 2 * m.n);
        m.furrow = malloc(sizeof(uint16_t) * m.n);
        m.ids = malloc(sizeof(uint32_t) * m.n);
        if (!m.normal || !m.furrow || !m.ids)
            r = sk_fail(&err, SK_ERROR_OUT_OF_MEMORY, "out of memory for the maps");
    }
    if (r == SK_OK && own_preview) r = sk_image_create(&m.preview, rw, rh, 3, &err);
    if (r == SK_OK && edges) r = sk_image_create(&m.edges, rw, rh, 3, &err);
    /* furrow.png spans half the furrow level's spacing: the whole ridge, centre to edge */
    float furrow_max = 0.5f * rd_desc->levels[furrow_level - 1].spacing_mm;
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "skin maps", !args->common.quiet);
    if (r == SK_OK)
        r = render_maps(&(band_job){.skin = skin,
                                    .m = &m,
                                    .w = w,
                                    .h = h,
                                    .region = {region[0], region[1], region[2], region[3]},
                                    .furrow_level = (int)furrow_level,
                                    .id_level = (int)id_level,
                                    .samples = (int)samples,
                                    .edges = edges,
                                    .furrow_max = furrow_max},
                        &bar, &err);
    sk_progress_bar_end(&bar);
    times.shading = phase_now();
    if (r == SK_OK)
        r = write_maps(skin, &m, staged, w, h, directx, edges, (int)furrow_level, furrow_max, &err);
    if (r == SK_OK)
        r = sk_output_set_commit(outputs, &err);
    else
        sk_output_set_abort(outputs);
    times.files = phase_now();
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
    map_store_free(&m);
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
