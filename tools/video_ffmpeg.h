/* The command's ffmpeg runner for the showcase's MP4 (tools/video_ffmpeg.c). */
#ifndef SK_TOOLS_VIDEO_FFMPEG_H
#define SK_TOOLS_VIDEO_FFMPEG_H

#include <stdbool.h>

#include "shitsukan/showcase.h"

/* True if `ffmpeg` runs (its -version exits 0). */
bool video_ffmpeg_available(const char *ffmpeg);
/* An sk_showcase_video_fn: `user` is the ffmpeg program (NULL: "ffmpeg" on the PATH). */
sk_result video_ffmpeg_encode(void *user, const char *frames_pattern, double fps, const char *wav,
                              const char *path, char *note, size_t note_size, bool *written,
                              sk_error *err);

#endif
