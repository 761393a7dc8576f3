/* `shitsukan wood cut` and `shitsukan wood sweep`: planar cuts through the wood solid
 * texture (Kawai 2000) as images, and the light swept through the incidence angle as a
 * numbered image sequence. Argument parsing, preset loading and file writing only. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "cli.h"
#include "shitsukan/io.h"
#include "shitsukan/maps.h"
#include "shitsukan/wood.h"

/* Options shared by both commands: the cut plane, its framing and the image. */
#define PLANE_OPTIONS                                                                              \
    {"size", 0, "N|WxH", "image size in pixels; default 1024 (cut), 512 (sweep)", false},          \
        {"region", 0, "x,y,w,h", "render only this sub-rectangle (same pixels as the full image)", \
         false},                                                                                   \
        {"plane", 0, "end|flat|quarter", "cut through the log (sets view.plane); default flat",    \
         false},                                                                                   \
        {"distance", 0, "MM",                                                                      \
         "flat: the plane's distance from the pith; quarter, end: the view centre's (view."        \
         "distance_mm)",                                                                           \
         false},                                                                                   \
        {"height", 0, "MM", "tree height y of the view centre (view.height_mm); default 0",        \
         false},                                                                                   \
        {"width-mm", 0, "MM", "width of the view in mm (view.width_mm); default 100", false},      \
        {"tilt", 0, "DEG", "turn the plane about the image's horizontal axis (view.tilt_deg)",     \
         false},                                                                                   \
        {"point", 0, "X,Y,Z", "any plane: the image centre in scene mm (with --normal, --axis)",   \
         false},                                                                                   \
        {"normal", 0, "X,Y,Z", "any plane: its normal, towards the viewer", false},                \
        {"axis", 0, "X,Y,Z", "any plane: the image's x direction (projected onto the plane)",      \
         false},                                                                                   \
        {"view-deg", 0, "DEG", "viewer turned from the normal towards the image top; default 0",   \
         false},                                                                                   \
    {                                                                                              \
        "samples", 0, "N", "samples per pixel along each axis (1-8); default 2", false             \
    }

static const cli_option k_cut_options[] = {
    PLANE_OPTIONS,
    {"light-deg", 0, "DEG",
     "delta: light turned from the normal towards the image top (view.light_deg)", false},
    {"light-azimuth", 0, "DEG", "the light's plane turned about the normal; default 0", false},
    {"maps", 0, "DIR", "also write albedo.png, fibre.png and pores.png into DIR", false},
};

static const cli_option k_sweep_options[] = {
    PLANE_OPTIONS,
    {"frames", 0, "N", "number of frames (2-10000); default 24", false},
    {"from-deg", 0, "DEG", "light incidence of the first frame; default -20", false},
    {"to-deg", 0, "DEG", "light incidence of the last frame; default 20", false},
    {"light-azimuth", 0, "DEG", "the light's plane turned about the normal; default 0", false},
};

/* "X,Y,Z" into a vector. */
static int parse_vec3(const char *option, const char *text, sk_vec3f *out)
{
    double v[3];
    int status = cli_parse_numbers(option, text, 3, v);
    if (status) return status;
    *out = sk_v3f((float)v[0], (float)v[1], (float)v[2]);
    return 0;
}

/* An angle option in degrees stored in radians. */
static int get_degrees(const cli_command *command, const cli_args *args, const char *name,
                       double lo, double hi, float *out)
{
    if (!cli_has(command, args, name)) return 0;
    double v;
    int status = cli_get_double(command, args, name, 0.0, lo, hi, &v);
    if (status) return status;
    *out = (float)(v * SK_DEG_TO_RAD);
    return 0;
}

static int get_mm(const cli_command *command, const cli_args *args, const char *name, double lo,
                  double hi, float *out)
{
    if (!cli_has(command, args, name)) return 0;
    double v;
    int status = cli_get_double(command, args, name, 0.0, lo, hi, &v);
    if (status) return status;
    *out = (float)v;
    return 0;
}

/* Everything both commands share: the tree, the cut and the image region. */
typedef struct wood_job {
    sk_wood *wood;
    sk_wood_cut_desc cut;
    int region[4];
    int samples;
} wood_job;

static int prepare(const cli_command *command, const cli_args *args, int default_size,
                   bool light_option, wood_job *job)
{
    memset(job, 0, sizeof *job);
    cli_apply_threads(args);
    sk_preset *preset;
    int status = cli_load_preset(command, args, &preset);
    if (status) return status;
    sk_wood_desc desc;
    memset(&desc, 0, sizeof desc);
    sk_error err = {0};
    sk_result r = sk_preset_bind(preset, &sk_wood_schema, &desc, &err);
    sk_preset_free(preset);
    if (r != SK_OK) return cli_fail_error(&err);

    /* view overrides go into the desc, so the tree's validation reports them */
    sk_wood_view_desc *view = &desc.view;
    const char *plane = cli_get(command, args, "plane");
    if (plane) {
        int found = -1;
        for (int i = 1; sk_wood_plane_names[i]; i++)
            if (strcmp(plane, sk_wood_plane_names[i]) == 0) found = i;
        if (found < 0)
            return cli_fail(CLI_EXIT_USAGE, "--plane '%s' must be end, flat or quarter", plane);
        view->plane = (sk_wood_plane)found;
    }
    if ((status = get_mm(command, args, "distance", 0.0, 10000.0, &view->distance_mm)) ||
        (status = get_mm(command, args, "height", -100000.0, 100000.0, &view->height_mm)) ||
        (status = get_mm(command, args, "width-mm", 0.01, 100000.0, &view->width_mm)) ||
        (status = get_degrees(command, args, "tilt", -90.0, 90.0, &view->tilt)) ||
        (status = get_degrees(command, args, "view-deg", -89.0, 89.0, &view->view_incidence)) ||
        (status = get_degrees(command, args, "light-azimuth", -180.0, 180.0, &view->light_azimuth)))
        return status;
    if (light_option &&
        (status = get_degrees(command, args, "light-deg", -89.0, 89.0, &view->light_incidence)))
        return status;
    long long samples;
    if ((status = cli_get_int(command, args, "samples", 2, 1, 8, &samples))) return status;
    job->samples = (int)samples;

    if (sk_wood_create(&desc, &job->wood, &err) != SK_OK) return cli_fail_error(&err);
    sk_wood_cut_desc *cut = &job->cut;
    sk_wood_view_cut(job->wood, &sk_wood_get_desc(job->wood)->view, cut);

    int given = cli_has(command, args, "point") + cli_has(command, args, "normal") +
                cli_has(command, args, "axis");
    if (given != 0 && given != 3) {
        sk_wood_destroy(job->wood);
        return cli_fail(CLI_EXIT_USAGE, "--point, --normal and --axis go together (any plane)");
    }
    if (given == 3 &&
        ((status = parse_vec3("point", cli_get(command, args, "point"), &cut->point)) ||
         (status = parse_vec3("normal", cli_get(command, args, "normal"), &cut->normal)) ||
         (status = parse_vec3("axis", cli_get(command, args, "axis"), &cut->axis)))) {
        sk_wood_destroy(job->wood);
        return status;
    }
    if ((status = cli_get_size(command, args, "size", default_size, default_size,
                               SK_IMAGE_MAX_DIMENSION, &cut->width, &cut->height))) {
        sk_wood_destroy(job->wood);
        return status;
    }
    job->region[2] = cut->width;
    job->region[3] = cut->height;
    const char *region = cli_get(command, args, "region");
    if (region && (status = cli_parse_region(region, cut->width, cut->height, job->region))) {
        sk_wood_destroy(job->wood);
        return status;
    }
    memcpy(cut->region, job->region, sizeof job->region);
    cut->samples = job->samples;
    return 0;
}

/* The image buffers of a job (`bytes_per_pixel` over its region) against the cap. */
static int check_memory(const cli_args *args, const wood_job *job, double bytes_per_pixel)
{
    char driver[96];
    snprintf(driver, sizeof driver, "a %d x %d image (--size, --region)", job->region[2],
             job->region[3]);
    int status = cli_check_image(job->region[2], job->region[3], 3, driver);
    if (status) return status;
    return cli_check_memory(args, cli_image_bytes(job->region[2], job->region[3], bytes_per_pixel),
                            driver);
}

static void describe(const wood_job *job, const char *command, sk_image_metadata *meta)
{
    char value[128];
    sk_image_metadata_set(meta, "shitsukan:command", command, NULL);
    snprintf(value, sizeof value, "%llu", (unsigned long long)sk_wood_get_desc(job->wood)->seed);
    sk_image_metadata_set(meta, "shitsukan:seed", value, NULL);
    snprintf(value, sizeof value, "%.6g", job->cut.width_mm / job->cut.width);
    sk_image_metadata_set(meta, SK_IMAGE_KEY_MM_PER_PIXEL, value, NULL);
    snprintf(value, sizeof value, "%.6g,%.6g,%.6g", job->cut.point.x, job->cut.point.y,
             job->cut.point.z);
    sk_image_metadata_set(meta, "shitsukan:plane_point_mm", value, NULL);
    snprintf(value, sizeof value, "%.6g,%.6g,%.6g", job->cut.normal.x, job->cut.normal.y,
             job->cut.normal.z);
    sk_image_metadata_set(meta, "shitsukan:plane_normal", value, NULL);
    snprintf(value, sizeof value, "%.6g,%.6g,%.6g", job->cut.axis.x, job->cut.axis.y,
             job->cut.axis.z);
    sk_image_metadata_set(meta, "shitsukan:plane_axis", value, NULL);
}

static const char *const k_color_formats[] = {".png", ".exr", NULL};

/* A colour image: float EXR for .exr, else an 8-bit sRGB PNG. */
static sk_result write_color(const sk_image *image, const char *path, const sk_image_metadata *meta,
                             sk_error *err)
{
    size_t n = strlen(path);
    if (n >= 4 && strcasecmp(path + n - 4, ".exr") == 0) {
        sk_exr_write_desc exr = {.metadata = meta};
        return sk_image_write_exr(image, path, &exr, err);
    }
    sk_png_write_desc png = {.bit_depth = 8, .encoding = SK_PNG_ENCODING_SRGB, .metadata = meta};
    return sk_image_write_png(image, path, &png, err);
}

/* The maps of `--maps` (sk_wood_map_info: their files and codes), one after another. */
static sk_result write_maps(const wood_job *job, const char *dir, const sk_image *maps,
                            sk_error *err)
{
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++) {
        const sk_map_info *info = sk_wood_map_info((sk_wood_map)k);
        char path[PATH_MAX];
        snprintf(path, sizeof path, "%s/%s", dir, info->file);
        sk_image_metadata meta = {0};
        describe(job, "wood cut", &meta);
        sk_result r = sk_wood_maps_metadata((sk_wood_map)k, &meta, err);
        sk_png_write_desc png = {.bit_depth = info->bit_depth,
                                 .encoding =
                                     info->srgb ? SK_PNG_ENCODING_SRGB : SK_PNG_ENCODING_LINEAR,
                                 .metadata = &meta};
        if (r == SK_OK) r = sk_image_write_png(&maps[k], path, &png, err);
        if (r != SK_OK) return r;
    }
    return SK_OK;
}

static int run_cut(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "wood cut: -o/--output is required");
    int format;
    int status = cli_output_format("-o", output, k_color_formats, &format);
    if (status) return status;
    wood_job job;
    if ((status = prepare(command, args, 1024, true, &job))) return status;
    const char *maps = cli_get(command, args, "maps");
    /* float images (shaded; albedo, fibre, pores with --maps) and their encodings */
    if ((status = check_memory(args, &job, maps ? 48 : 16))) {
        sk_wood_destroy(job.wood);
        return status;
    }
    sk_image shaded = {0}, images[SK_WOOD_MAP_COUNT] = {{0}};
    sk_error err = {0};
    int w = job.region[2], h = job.region[3];
    /* the picture and the maps folder appear together at the end, or neither */
    sk_output_set *outputs = NULL;
    const char *staged_output = NULL, *staged_maps = NULL;
    sk_result r = sk_output_set_create(&outputs, &err);
    /* the folder first: the picture may go inside it (-o DIR/shaded.png --maps DIR) */
    if (r == SK_OK && maps) r = sk_output_set_folder(outputs, maps, &staged_maps, &err);
    if (r == SK_OK) r = sk_output_set_file(outputs, output, &staged_output, &err);
    if (r == SK_OK) r = sk_image_create(&shaded, w, h, 3, &err);
    for (int k = 0; k < SK_WOOD_MAP_COUNT && maps && r == SK_OK; k++) {
        r = sk_image_create(&images[k], w, h, sk_wood_map_info((sk_wood_map)k)->channels, &err);
        if (r == SK_OK) *sk_wood_maps_cut_output(&job.cut, (sk_wood_map)k) = images[k].data;
    }
    if (r == SK_OK) {
        job.cut.shaded = shaded.data;
        sk_progress_bar bar;
        sk_progress_bar_begin(&bar, "wood cut", !args->common.quiet);
        job.cut.progress = sk_progress_bar_sink(&bar);
        r = sk_wood_cut(job.wood, &job.cut, &err);
        sk_progress_bar_end(&bar);
    }
    if (r == SK_OK) {
        sk_image_metadata meta = {0};
        describe(&job, "wood cut", &meta);
        r = write_color(&shaded, staged_output, &meta, &err);
    }
    if (r == SK_OK && maps) r = write_maps(&job, staged_maps, images, &err);
    if (r == SK_OK)
        r = sk_output_set_commit(outputs, &err);
    else
        sk_output_set_abort(outputs);
    sk_image_free(&shaded);
    for (int k = 0; k < SK_WOOD_MAP_COUNT; k++) sk_image_free(&images[k]);
    sk_wood_destroy(job.wood);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

static int run_sweep(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "wood sweep: -o/--output DIR is required");
    long long frames;
    double from, to;
    int status;
    if ((status = cli_get_int(command, args, "frames", 24, 2, 10000, &frames)) ||
        (status = cli_get_double(command, args, "from-deg", -20.0, -89.0, 89.0, &from)) ||
        (status = cli_get_double(command, args, "to-deg", 20.0, -89.0, 89.0, &to)))
        return status;
    wood_job job;
    if ((status = prepare(command, args, 512, false, &job))) return status;
    /* one float frame and its encoding */
    if ((status = check_memory(args, &job, 16))) {
        sk_wood_destroy(job.wood);
        return status;
    }
    sk_error err = {0};
    sk_image frame = {0};
    /* the frames appear together at the end, or none */
    sk_output_set *outputs = NULL;
    const char *staged = NULL;
    sk_result r = sk_output_set_create(&outputs, &err);
    if (r == SK_OK) r = sk_output_set_folder(outputs, output, &staged, &err);
    if (r == SK_OK) r = sk_image_create(&frame, job.region[2], job.region[3], 3, &err);
    job.cut.shaded = frame.data;
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "wood sweep", !args->common.quiet);
    for (long long f = 0; f < frames && r == SK_OK; f++) {
        double delta = from + (to - from) * (double)f / (double)(frames - 1);
        job.cut.light_incidence = (float)(delta * SK_DEG_TO_RAD);
        r = sk_wood_cut(job.wood, &job.cut, &err);
        if (r != SK_OK) break;
        sk_image_metadata meta = {0};
        describe(&job, "wood sweep", &meta);
        char value[32], path[PATH_MAX];
        snprintf(value, sizeof value, "%.4f", delta);
        sk_image_metadata_set(&meta, "shitsukan:light_deg", value, NULL);
        snprintf(path, sizeof path, "%s/frame_%04lld.png", staged, f + 1);
        r = write_color(&frame, path, &meta, &err);
        sk_progress_bar_update(&bar, (double)(f + 1) / (double)frames);
    }
    sk_progress_bar_end(&bar);
    if (r == SK_OK)
        r = sk_output_set_commit(outputs, &err);
    else
        sk_output_set_abort(outputs);
    sk_image_free(&frame);
    sk_wood_destroy(job.wood);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

const cli_command cmd_wood_cut = {
    .name = "wood cut",
    .summary = "a planar cut through the wood solid texture (shaded preview + maps)",
    .usage = "shitsukan wood cut [options] -o OUT.png|OUT.exr",
    .description =
        "Cuts the log of Kawai 2000's wood model (rings, grain, vessels, fibre streaks)\n"
        "along a plane and renders it under a parallel light: end grain (cross-cut),\n"
        "flat-sawn (tangential) or quarter-sawn (radial), or any plane given by a point,\n"
        "a normal and an in-plane x axis, all in millimetres. The light is turned from\n"
        "the normal towards the image top by delta (eq. 4); for flat and quarter cuts the\n"
        "image top is the tree top. The preview is an 8-bit sRGB PNG (or float EXR).\n"
        "--maps DIR adds albedo.png (sRGB), fibre.png (16-bit linear: rgb = 0.5 + 0.5 f,\n"
        "f the unit fibre direction up the tree with x right, y up, z towards the\n"
        "viewer; a tangent map for anisotropic shaders) and pores.png (vessel coverage).",
    .examples =
        "  shitsukan wood cut --preset fig9 --size 2048 -o cut.png\n"
        "  shitsukan wood cut --preset oak --plane quarter --maps oak-maps -o oak.png\n"
        "  shitsukan wood cut --preset maple --plane end --width-mm 20 -o end.png\n"
        "  shitsukan wood cut --preset ash --point 0,0,60 --normal 0,0.5,1 --axis 1,0,0 -o o.png",
    .options = k_cut_options,
    .option_count = (int)(sizeof k_cut_options / sizeof k_cut_options[0]),
    .common = CLI_COMMON_ALL,
    .preset_module = "wood",
    .schema = &sk_wood_schema,
    .run = run_cut,
};

const cli_command cmd_wood_sweep = {
    .name = "wood sweep",
    .summary = "the light swept through the incidence angle over a cut (PNG frames)",
    .usage = "shitsukan wood sweep [options] -o DIR",
    .description =
        "Renders the same planar cut as 'wood cut' once per frame with the light's\n"
        "incidence delta stepped evenly from --from-deg to --to-deg, so the moving sheen\n"
        "of figured wood (Kawai 2000 sec. 7, Fig. 9) can be watched. Frames are written\n"
        "as DIR/frame_0001.png, frame_0002.png, ... (8-bit sRGB).",
    .examples = "  shitsukan wood sweep --preset fig9 --frames 24 -o sweep\n"
                "  ffmpeg -framerate 12 -i sweep/frame_%04d.png sweep.mp4",
    .options = k_sweep_options,
    .option_count = (int)(sizeof k_sweep_options / sizeof k_sweep_options[0]),
    .common = CLI_COMMON_ALL,
    .preset_module = "wood",
    .schema = &sk_wood_schema,
    .run = run_sweep,
};
