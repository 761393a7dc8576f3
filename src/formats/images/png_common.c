/* libpng error, warning and allocation callbacks shared by the PNG reader and writer. */
#include <stdio.h>
#include <stdlib.h>

#include "formats/images/png_internal.h"

void sk__png_on_error(png_structp png, png_const_charp message)
{
    sk__png_error *error = png_get_error_ptr(png);
    if (error) snprintf(error->message, sizeof error->message, "%s", message ? message : "");
    png_longjmp(png, 1);
}

void sk__png_on_warning(png_structp png, png_const_charp message)
{
    (void)png;
    (void)message;
}

png_voidp sk__png_malloc(png_structp png, png_alloc_size_t size)
{
    (void)png;
    return size <= SK__PNG_MAX_ALLOCATION ? malloc(size) : NULL;
}

void sk__png_free(png_structp png, png_voidp ptr)
{
    (void)png;
    free(ptr);
}
