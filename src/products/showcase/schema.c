/* Preset schema of the showcase's numbers (sk_showcase_desc): the frames, the hand's
 * surface and texture, the keyboard, the fingering costs, how the hand plays (beyond the
 * thesis's press, Fig. 4.21) and the piano tone. Each key's range and default are stated
 * here once; the showcase's checks read them. The melody, stage, coupling and forearm
 * are files (the command's options and the stage preset). */
#include <stddef.h>

#include "products/showcase/showcase_internal.h"

static const sk_schema_field piano_fields[] = {
    SK_SCHEMA_DOUBLE(sk_piano_desc, white_pitch_mm, "white_pitch_mm", 15, 30,
                     .flags = SK_FIELD_ZERO, .def = 23.5,
                     .doc = "white keys' centre spacing (an octave 7 times it)"),
    SK_SCHEMA_DOUBLE(sk_piano_desc, dip_mm, "dip_mm", 2, 20, .flags = SK_FIELD_ZERO, .def = 10,
                     .doc = "key dip at the front"),
    SK_SCHEMA_DOUBLE(sk_piano_desc, pivot_mm, "pivot_mm", 100, 600, .flags = SK_FIELD_ZERO,
                     .def = 250, .doc = "from a key's front to its pivot"),
    SK_SCHEMA_DOUBLE(sk_piano_desc, white_top_mm, "white_top_mm", 0, 5000, .def = 747,
                     .doc = "height of the white keys' tops at rest"),
    SK_SCHEMA_DOUBLE(sk_piano_desc, front_mm, "front_mm", -5000, 5000, .def = 275,
                     .doc = "z of the keys' fronts"),
};
const sk_schema sk__piano_schema = SK_SCHEMA_OF("piano", sk_piano_desc, piano_fields);

static const sk_schema_field fingering_fields[] = {
    SK_SCHEMA_DOUBLE(sk_fingering_desc, reach_mm, "reach_mm", 0, 200, .def = 30,
                     .doc = "notes held together: the largest difference between their keys' "
                            "spacing and their fingers' the spread can make up"),
    SK_SCHEMA_DOUBLE(sk_fingering_desc, pitch_mm, "pitch_mm", 1, 100, .flags = SK_FIELD_ZERO,
                     .def_text = "the piano's white_pitch_mm",
                     .doc = "a white key's width for the costs"),
    SK_SCHEMA_DOUBLE(sk_fingering_desc, spacing_mm, "spacing_mm", 0, 50, .def = 17,
                     .doc = "neighbouring fingers busy at once need keys at least this far "
                            "apart"),
    SK_SCHEMA_DOUBLE(sk_fingering_desc, busy_before_s, "busy_before_s", 0, 2, .def = 0.12,
                     .doc = "a finger is busy from this long before its note"),
    SK_SCHEMA_DOUBLE(sk_fingering_desc, busy_after_s, "busy_after_s", 0, 2, .def = 0.14,
                     .doc = "... to this long after"),
    SK_SCHEMA_DOUBLE(sk_fingering_desc, move_gap_s, "move_gap_s", 0, 1000, .def = 0.05,
                     .doc = "the least silence in which one finger moves to another key"),
};
const sk_schema sk__fingering_schema =
    SK_SCHEMA_OF("fingering", sk_fingering_desc, fingering_fields);

static const sk_schema_field performance_fields[] = {
    SK_SCHEMA_DOUBLE(sk_performance_desc, approach_s, "approach_s", 0.02, 1, .flags = SK_FIELD_ZERO,
                     .def = 0.12,
                     .doc = "a finger starts down this long before its key is half down (the "
                            "note's start); more than half of descent_s"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, descent_s, "descent_s", 0.005, 0.2,
                     .flags = SK_FIELD_ZERO, .def = 0.04, .doc = "key travel, top to bottom"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, lift_s, "lift_s", 0.02, 1, .flags = SK_FIELD_ZERO,
                     .def = 0.12, .doc = "back up to the hover height after the key is up"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, hover_mm, "hover_mm", 2, 40, .flags = SK_FIELD_ZERO,
                     .def = 6, .doc = "fingertips above the white keys in the playing posture"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, clearance_mm, "clearance_mm", 0, 10, .def = 1,
                     .doc = "a finger that does not play stays at least this above any key"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, press_pip_ratio, "press_pip_ratio", 0, 4,
                     .def = 0.5 / 0.9,
                     .doc = "PIP torque per MCP torque of a press (the thesis's piano demo: 0.5 "
                            "/ 0.9)"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, travel_s, "travel_s", 0.01, 2, .flags = SK_FIELD_ZERO,
                     .def = 0.04,
                     .doc = "how far in time the wrist looks to the notes before and after"),
    SK_SCHEMA_DOUBLE(sk_performance_desc, strike_drop_mm, "strike_drop_mm", -1, 10, .def = 1.5,
                     .doc = "the wrist gives way this much at a strike and recovers (negative: "
                            "none)"),
};
const sk_schema sk__performance_schema =
    SK_SCHEMA_OF("performance", sk_performance_desc, performance_fields);

/* Fletcher 1964 (inharmonicity), Weinreich 1977 (two-stage decay). */
static const sk_schema_field synth_fields[] = {
    SK_SCHEMA_INT(sk_synth_desc, sample_rate, "sample_rate", 8000, 192000, .flags = SK_FIELD_ZERO,
                  .def = 44100, .doc = "samples per second of the WAV"),
    SK_SCHEMA_DOUBLE(sk_synth_desc, gain, "gain", 1e-6, 1, .flags = SK_FIELD_ZERO, .def = 0.25,
                     .doc = "level of a note of velocity 127"),
    SK_SCHEMA_DOUBLE(sk_synth_desc, inharmonicity, "inharmonicity", -1, 0.01, .def = 0.0004,
                     .doc = "string inharmonicity B at C4, scaled by pitch (negative: none)"),
    SK_SCHEMA_DOUBLE(sk_synth_desc, decay_s, "decay_s", 0.1, 60, .flags = SK_FIELD_ZERO, .def = 3,
                     .doc = "aftersound time constant at C4"),
    SK_SCHEMA_DOUBLE(sk_synth_desc, release_s, "release_s", 0.005, 5, .flags = SK_FIELD_ZERO,
                     .def = 0.1, .doc = "damper time constant"),
    SK_SCHEMA_DOUBLE(sk_synth_desc, tail_s, "tail_s", 0, 30, .def = 1,
                     .doc = "sound kept after the last note ends"),
};
const sk_schema sk__synth_schema = SK_SCHEMA_OF("synth", sk_synth_desc, synth_fields);

/* The frame keys first: sk__showcase_frame_schema is a view of them. */
static const sk_schema_field showcase_fields[] = {
    SK_SCHEMA_DOUBLE(sk_showcase_desc, fps, "fps", 1, 240, .flags = SK_FIELD_ZERO, .def = 24,
                     .doc = "frames per second"),
    SK_SCHEMA_INT(sk_showcase_desc, width, "width", 16, 8192, .flags = SK_FIELD_ZERO, .def = 1280,
                  .doc = "frame width in pixels"),
    SK_SCHEMA_INT(sk_showcase_desc, height, "height", 16, 8192, .flags = SK_FIELD_ZERO, .def = 720,
                  .doc = "frame height in pixels"),
    SK_SCHEMA_INT(sk_showcase_desc, samples, "samples", 1, 1024, .flags = SK_FIELD_ZERO, .def = 16,
                  .doc = "camera samples per pixel"),
    SK_SCHEMA_INT(sk_showcase_desc, texture_size, "texture_size", 64, 8192, .flags = SK_FIELD_ZERO,
                  .def = 1024, .doc = "the hand's skin texture (atlas) in pixels"),
    SK_SCHEMA_INT(sk_showcase_desc, hand_triangles, "hand_triangles", 500, 200000,
                  .flags = SK_FIELD_ZERO, .def = 8000,
                  .doc = "triangles of the hand's surface (8000: the thesis's)"),
    SK_SCHEMA_OBJECT(sk_showcase_desc, piano, "piano", sk__piano_schema, .doc = "the keyboard"),
    SK_SCHEMA_OBJECT(sk_showcase_desc, fingering, "fingering", sk__fingering_schema,
                     .doc = "the costs of the automatic fingering"),
    SK_SCHEMA_OBJECT(sk_showcase_desc, performance, "performance", sk__performance_schema,
                     .doc = "how the hand plays"),
    SK_SCHEMA_OBJECT(sk_showcase_desc, synth, "synth", sk__synth_schema, .doc = "the piano tone"),
};
const sk_schema sk_showcase_schema = SK_SCHEMA_OF("showcase", sk_showcase_desc, showcase_fields);
const sk_schema sk__showcase_frame_schema = {"showcase", showcase_fields, 6, "sk_showcase_desc"};
