/* `shitsukan noise`: tileable fBm noise maps (PNG 8/16-bit or float EXR). */
#include <string.h>

#include "cli.h"
#include "shitsukan/noise_map.h"

static const cli_option k_options[] = {
    {"size", 0, "N|WxH", "map size in pixels (overrides the preset's width/height); default 512",
     false},
    {"region", 0, "x,y,w,h", "render only this sub-rectangle (same pixels as the full map)", false},
    {"bits", 0, "8|16", "PNG bit depth; default 16", false},
};

static int run_noise(const cli_command *command, const cli_args *args)
{
    const char *output = args->common.output;
    if (!output) return cli_fail(CLI_EXIT_USAGE, "noise: -o/--output is required");
    sk_preset *preset;
    int status = cli_load_preset(command, args, &preset);
    if (status) return status;
    sk_noise_map_desc desc;
    memset(&desc, 0, sizeof desc);
    sk_error err = {0};
    sk_result r = sk_preset_bind(preset, &sk_noise_map_schema, &desc, &err);
    sk_preset_free(preset);
    if (r != SK_OK) return cli_fail_error(&err);
    long long bits;
    if ((status = cli_get_int(command, args, "bits", 16, 8, 16, &bits))) return status;
    if (bits != 8 && bits != 16) return cli_fail(CLI_EXIT_USAGE, "--bits must be 8 or 16");
    if (cli_has(command, args, "size") &&
        (status = cli_get_size(command, args, "size", 512, 512, SK_IMAGE_MAX_DIMENSION, &desc.width,
                               &desc.height)))
        return status;
    desc = sk_noise_map_desc_resolved(&desc);
    if (sk_noise_map_desc_validate(&desc, &err) != SK_OK) return cli_fail_error(&err);
    int region[4] = {0, 0, desc.width, desc.height};
    const char *region_text = cli_get(command, args, "region");
    if (region_text && (status = cli_parse_region(region_text, desc.width, desc.height, region)))
        return status;
    static const char *const k_formats[] = {".png", ".exr", NULL};
    int format;
    if ((status = cli_output_format("-o", output, k_formats, &format))) return status;
    char driver[96];
    snprintf(driver, sizeof driver, "a %d x %d map (--size, --region)", region[2], region[3]);
    /* the float map and its encoding */
    if ((status = cli_check_image(region[2], region[3], 1, driver)) ||
        (status = cli_check_memory(args, cli_image_bytes(region[2], region[3], 12), driver)))
        return status;

    sk_image image = {0};
    if (sk_image_create(&image, region[2], region[3], 1, &err) != SK_OK)
        return cli_fail_error(&err);
    sk_progress_bar bar;
    sk_progress_bar_begin(&bar, "noise", !args->common.quiet);
    desc.progress = sk_progress_bar_sink(&bar);
    r = sk_noise_map_render(&desc, region, &image, &err);
    sk_progress_bar_end(&bar);
    if (r == SK_OK) {
        sk_image_metadata meta = {0};
        char value[32];
        snprintf(value, sizeof value, "%llu", (unsigned long long)desc.seed);
        sk_image_metadata_set(&meta, "shitsukan:seed", value, NULL);
        sk_image_metadata_set(&meta, "shitsukan:command", "noise", NULL);
        if (format == 1) {
            sk_exr_write_desc exr = {.metadata = &meta};
            r = sk_image_write_exr(&image, output, &exr, &err);
        } else {
            sk_png_write_desc png = {
                .bit_depth = (int)bits, .encoding = SK_PNG_ENCODING_LINEAR, .metadata = &meta};
            r = sk_image_write_png(&image, output, &png, &err);
        }
    }
    sk_image_free(&image);
    return r == SK_OK ? CLI_EXIT_OK : cli_fail_error(&err);
}

const cli_command cmd_noise = {
    .name = "noise",
    .summary = "tileable fBm noise maps (PNG or EXR)",
    .usage = "shitsukan noise [options] -o OUT.png|OUT.exr",
    .description =
        "Renders fractal gradient noise (fBm) into a grey map in [0, 1]. With 'seamless'\n"
        "(on in the shipped presets) the map tiles without a seam. PNG output is linear\n"
        "(no sRGB curve), 16-bit by default; .exr output is 32-bit float.",
    .examples = "  shitsukan noise --preset clouds --size 1024 -o clouds.png\n"
                "  shitsukan noise --set cells=16 --set octaves=3 --set seamless=true -o n.exr",
    .options = k_options,
    .option_count = (int)(sizeof k_options / sizeof k_options[0]),
    .common = CLI_COMMON_ALL,
    .min_positional = 0,
    .max_positional = 0,
    .preset_module = "noise",
    .schema = &sk_noise_map_schema,
    .run = run_noise,
};
