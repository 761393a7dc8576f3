/* The fBm parameters' keys, ranges and defaults, stated once: the fBm desc's own schema
 * (src/base/noise.c) and every schema that holds an sk_fbm_desc (the noise map's) are
 * made of these fields. */
#ifndef SK_FBM_FIELDS_H
#define SK_FBM_FIELDS_H

#include <stddef.h>

#include "shitsukan/schema.h"

/* The three fields of an sk_fbm_desc held at members octaves_, lacunarity_, gain_ of T. */
#define SK__FBM_FIELDS(T, octaves_, lacunarity_, gain_)                                            \
    SK_SCHEMA_INT(T, octaves_, "octaves", 1, 16, .def = 5, .doc = "fBm octaves"),                  \
        SK_SCHEMA_FLOAT(T, lacunarity_, "lacunarity", 1.0001, 8, .def = 2,                         \
                        .doc = "frequency ratio between octaves"),                                 \
        SK_SCHEMA_FLOAT(T, gain_, "gain", 0.0001, 0.9999, .def = 0.5,                              \
                        .doc = "amplitude ratio between octaves")

/* The schema of sk_fbm_desc alone (keys octaves, lacunarity, gain). */
extern const sk_schema sk__fbm_schema;

#endif
