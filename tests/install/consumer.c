/* A program outside the project that uses the installed library and headers. */
#include <stdio.h>

#include <shitsukan/core.h>
#include <shitsukan/image.h>

int main(void)
{
    sk_image img = {0};
    if (sk_image_create(&img, 4, 4, 1, NULL) != SK_OK) return 1;
    img.data[0] = sk_noise2(1, 0.5f, 0.25f);
    sk_image_free(&img);
    printf("%s %s\n", SK_VERSION_STRING, sk_result_string(SK_OK));
    return 0;
}
