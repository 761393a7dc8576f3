/* The whole run: the frames of a range into <dir>/frames, the sound and the fingering,
 * and the MP4 once every frame of the piece is in the folder (so runs over parts of the
 * frames, in any order or on several machines sharing the folder, join into one video). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "shitsukan/io.h"
#include "products/showcase/showcase_internal.h"

static int frame_digits(int count)
{
    int d = 1;
    for (int n = count - 1; n >= 10; n /= 10) d++;
    return d < 4 ? 4 : d;
}

static void frame_path(const char *dir, int digits, int frame, char *out, size_t size)
{
    snprintf(out, size, "%s/frames/frame_%0*d.png", dir, digits, frame);
}

sk_result sk_showcase_write_wav(const sk_showcase *sc, const char *path, sk_error *err)
{
    int rate = sc->desc.synth.sample_rate ? sc->desc.synth.sample_rate : 44100;
    size_t count = (size_t)((double)sc->frame_count / sc->desc.fps * rate + 0.5);
    float *samples = malloc((count > 0 ? count : 1) * sizeof *samples);
    if (!samples)
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory for %zu samples", count);
    sk_result r = sk_synth_render(&sc->melody, &sc->desc.synth, samples, count, err);
    if (r == SK_OK) r = sk_wav_write(path, samples, count, 1, rate, err);
    free(samples);
    return r;
}

sk_result sk_showcase_check_output(const sk_showcase_run_desc *desc, sk_error *err)
{
    if (!desc || !desc->output_dir || !desc->output_dir[0])
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT, "showcase run: no output folder");
    struct stat st;
    if (stat(desc->output_dir, &st) == 0 && !S_ISDIR(st.st_mode))
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "%s: exists and is not a folder (the output is a folder)", desc->output_dir);
    return SK_OK;
}

sk_result sk_showcase_run(sk_showcase *sc, const sk_showcase_run_desc *desc,
                          sk_showcase_stats *stats, sk_error *err)
{
    sk_showcase_stats local;
    if (!stats) stats = &local;
    memset(stats, 0, sizeof *stats);
    sk_result checked = sk_showcase_check_output(desc, err);
    if (checked != SK_OK) return checked;
    int first = desc->first_frame,
        last = desc->last_frame < 0 ? sc->frame_count - 1 : desc->last_frame;
    if (first < 0 || first >= sc->frame_count || last < first || last >= sc->frame_count)
        return sk_fail(err, SK_ERROR_INVALID_ARGUMENT,
                       "frames %d:%d are out of range: the piece has frames 0:%d", first, last,
                       sc->frame_count - 1);
    const char *dir = desc->output_dir;
    size_t size = strlen(dir) + 64;
    char *path = malloc(size), *wav = malloc(size);
    if (!path || !wav) {
        free(path), free(wav);
        return sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
    }
    snprintf(path, size, "%s/frames", dir);
    sk_result r = sk_make_dirs(path, err);
    int digits = frame_digits(sc->frame_count);
    snprintf(wav, size, "%s/showcase.wav", dir);
    if (r == SK_OK && !desc->join_only) {
        double t0 = sk_time_seconds();
        snprintf(path, size, "%s/fingering.txt", dir);
        r = sk_melody_write_text(&sc->melody, path, err);
        if (r == SK_OK) r = sk_showcase_write_wav(sc, wav, err);
        stats->seconds_audio = sk_time_seconds() - t0;
    }
    for (int f = first; r == SK_OK && !desc->join_only && f <= last; f++) {
        sk_image image;
        r = sk_showcase_render_frame(sc, f, &image, stats, err);
        if (r == SK_OK) {
            double t0 = sk_time_seconds();
            frame_path(dir, digits, f, path, size);
            sk_image_metadata meta = {0};
            sk_image_metadata_set(&meta, "Software", "shitsukan " SK_VERSION_STRING, NULL);
            r = sk_render_write(&image, &sc->stage->film, path, &meta, err);
            stats->seconds_write += sk_time_seconds() - t0;
        }
        sk_image_free(&image);
        sk_progress_report(&desc->progress, (double)(f - first + 1) / (last - first + 1));
    }
    /* the MP4, once the folder holds every frame */
    bool complete = r == SK_OK;
    for (int f = 0; complete && f < sc->frame_count; f++) {
        frame_path(dir, digits, f, path, size);
        struct stat st;
        complete = stat(path, &st) == 0;
    }
    struct stat wav_stat;
    if (r == SK_OK && complete && stat(wav, &wav_stat) != 0) complete = false;
    if (r == SK_OK && !desc->no_video) {
        if (!desc->encode_video) {
            snprintf(stats->video_note, sizeof stats->video_note,
                     "no MP4: no video encoder was given (the shitsukan command's runs ffmpeg)");
        } else if (!complete) {
            snprintf(stats->video_note, sizeof stats->video_note,
                     "no MP4 yet: the folder does not hold all %d frames and the WAV (render the "
                     "others, then "
                     "join)",
                     sc->frame_count);
        } else {
            double t0 = sk_time_seconds();
            char *pattern = malloc(size), *mp4 = malloc(size);
            if (!pattern || !mp4) {
                r = sk_fail(err, SK_ERROR_OUT_OF_MEMORY, "out of memory");
            } else {
                snprintf(pattern, size, "%s/frames/frame_%%0%dd.png", dir, digits);
                snprintf(mp4, size, "%s/showcase.mp4", dir);
                r = desc->encode_video(desc->encode_video_user, pattern, sc->desc.fps, wav, mp4,
                                       stats->video_note, sizeof stats->video_note,
                                       &stats->video_written, err);
            }
            free(pattern), free(mp4);
            stats->seconds_video = sk_time_seconds() - t0;
        }
    }
    free(path), free(wav);
    return r;
}
