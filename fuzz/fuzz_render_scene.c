/* Fuzz harness: a scene file (JSON) bound and validated; a scene that binds is built and
 * rendered at 4 x 4 pixels with its sizes capped (skin and wood materials are made
 * standard so that a huge skin tile or log cannot stall the run; their own harnesses
 * cover them). */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/render.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_preset *tree = NULL;
    if (sk_preset_parse(&tree, (const char *)data, size, "fuzz", NULL) != SK_OK) return 0;
    sk_render_scene_desc *d = malloc(sizeof *d);
    if (!d) abort();
    if (sk_render_scene_desc_bind(tree, NULL, d, NULL) == SK_OK) {
        d->image.width = d->image.height = 4;
        d->image.samples = 1;
        if (d->environment.ao_samples > 2) d->environment.ao_samples = 2;
        for (int i = 0; i < d->material_count; i++)
            d->materials[i].type = SK_RENDER_MATERIAL_STANDARD;
        for (int i = 0; i < d->object_count; i++) {
            if (d->objects[i].segments > 16) d->objects[i].segments = 16;
            if (d->objects[i].rings > 8) d->objects[i].rings = 8;
        }
        for (int i = 0; i < d->light_count; i++)
            if (d->lights[i].samples > 2) d->lights[i].samples = 2;
        sk_render_scene *scene = NULL;
        if (sk_render_scene_create(d, &scene, NULL) == SK_OK) {
            sk_image image = {0};
            if (sk_render_scene_render(scene, NULL, &image, NULL, NULL) == SK_OK) {
                sk_image display = {0};
                sk_render_tonemap(&image, &sk_render_scene_get_desc(scene)->film, &display, NULL);
                sk_image_free(&display);
            }
            sk_image_free(&image);
            sk_render_scene_destroy(scene);
        }
    }
    free(d);
    sk_preset_free(tree);
    return 0;
}
