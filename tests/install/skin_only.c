/* A program that wants skin maps only: it links the installed shitsukan-skin module (and
 * the base below it), not the umbrella library. tests/install/check.sh builds it with
 * `pkg-config shitsukan-skin` and checks which shared libraries it needs. */
#include <stdio.h>
#include <stdlib.h>

#include <shitsukan/skin.h>

int main(void)
{
    sk_error err = {0};
    sk_skin_desc desc = {0}; /* every key at its default */
    sk_skin *skin = NULL;
    if (sk_skin_create(&skin, &desc, &err) != SK_OK) {
        fprintf(stderr, "skin_only: %s\n", err.message);
        return 1;
    }
    enum { N = 32 };
    float *height = malloc(sizeof(float) * N * N);
    sk_skin_render_desc rd = {.width = N, .height = N, .height_mm = height};
    sk_result r = height ? sk_skin_render(skin, &rd, &err) : SK_ERROR_OUT_OF_MEMORY;
    float lo = 1e9f, hi = -1e9f;
    for (int i = 0; r == SK_OK && i < N * N; i++) {
        if (height[i] < lo) lo = height[i];
        if (height[i] > hi) hi = height[i];
    }
    free(height);
    sk_skin_destroy(skin);
    if (r != SK_OK || !(hi > lo)) {
        fprintf(stderr, "skin_only: %s\n", r != SK_OK ? err.message : "a flat height map");
        return 1;
    }
    printf("skin heights %.4f..%.4f mm\n", lo, hi);
    return 0;
}
