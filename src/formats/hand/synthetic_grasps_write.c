/* The synthetic grasp recordings written as a CSV file. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "models/hand/hand_internal.h"
#include "shitsukan/hand.h"
#include "formats/hand/hand_json_internal.h"

sk_result sk_hand_synthetic_grasps_write(const sk_hand_synthetic_desc *desc, const char *path,
                                         sk_error *err)
{
    char *text = NULL;
    size_t length = 0;
    sk_result r = sk_hand_synthetic_grasps_csv(desc, &text, &length, err);
    if (r != SK_OK) return r;
    r = sk__hand_write_text_file(path, text, err);
    free(text);
    return r;
}
