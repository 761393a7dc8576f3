/* Private libpng glue shared by the PNG reader and writer (not installed). */
#ifndef SK_IO_PNG_INTERNAL_H
#define SK_IO_PNG_INTERNAL_H

#include <png.h>

/* libpng reports errors through a callback that must not return: the callback stores
 * libpng's message here (the struct is the png "error pointer") and long-jumps back to
 * the setjmp in the function that drives libpng. */
typedef struct sk__png_error {
    char message[192];
} sk__png_error;

void sk__png_on_error(png_structp png, png_const_charp message);
/* Warnings (e.g. a bad CRC on an ancillary chunk, which libpng then skips) are not
 * printed: a library does not write to stderr. */
void sk__png_on_warning(png_structp png, png_const_charp message);

#endif
