/* The command's video encoder for the showcase (sk_showcase_video_fn): the MP4 of the
 * frames and the sound, made by ffmpeg (libx264, yuv420p; odd sizes padded to even; the
 * WAV as AAC), written to a temporary file and renamed into place. Without ffmpeg the
 * reason is returned as a note, not an error. The library runs no program itself. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "shitsukan/io.h"
#include "video_ffmpeg.h"

extern char **environ;

/* Runs argv, its stdout dropped and its stderr kept (first line in `message`); returns
 * the exit status, or -1 if the program could not be started. */
static int run_program(char *const argv[], char *message, size_t size)
{
    int fds[2];
    if (pipe(fds) != 0) return -1;
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    pid_t pid;
    int rc = posix_spawnp(&pid, argv[0], &actions, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    close(fds[1]);
    size_t used = 0;
    bool first_line = true;
    char buf[512];
    ssize_t n;
    if (message && size) message[0] = '\0';
    while ((n = read(fds[0], buf, sizeof buf)) > 0 || (n < 0 && errno == EINTR)) {
        for (ssize_t i = 0; i < n && message && first_line; i++) {
            if (buf[i] == '\n') {
                first_line = used == 0; /* skip leading empty lines */
                continue;
            }
            if (used + 1 < size) message[used++] = buf[i], message[used] = '\0';
        }
    }
    close(fds[0]);
    if (rc != 0) return -1;
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool video_ffmpeg_available(const char *ffmpeg)
{
    char *argv[] = {(char *)ffmpeg, "-hide_banner", "-version", NULL};
    return run_program(argv, NULL, 0) == 0;
}

sk_result video_ffmpeg_encode(void *user, const char *frames_pattern, double fps, const char *wav,
                              const char *path, char *note, size_t note_size, bool *written,
                              sk_error *err)
{
    const char *ffmpeg = user ? (const char *)user : "ffmpeg";
    *written = false;
    if (!video_ffmpeg_available(ffmpeg)) {
        snprintf(note, note_size,
                 "%s is not available: no MP4 (the frames and the WAV are written)", ffmpeg);
        return SK_OK;
    }
    sk_atomic_file f;
    sk_result r = sk_atomic_file_open(&f, path, err);
    if (r != SK_OK) return r;
    char rate[32];
    snprintf(rate, sizeof rate, "%.9g", fps);
    char *argv[] = {(char *)ffmpeg,
                    "-hide_banner",
                    "-loglevel",
                    "error",
                    "-y",
                    "-framerate",
                    rate,
                    "-i",
                    (char *)frames_pattern,
                    "-i",
                    (char *)wav,
                    "-map",
                    "0:v:0",
                    "-map",
                    "1:a:0",
                    "-vf",
                    "pad=ceil(iw/2)*2:ceil(ih/2)*2",
                    "-c:v",
                    "libx264",
                    "-pix_fmt",
                    "yuv420p",
                    "-crf",
                    "18",
                    "-c:a",
                    "aac",
                    "-b:a",
                    "160k",
                    "-shortest",
                    "-movflags",
                    "+faststart",
                    "-f",
                    "mp4",
                    f.temp_path,
                    NULL};
    char message[256];
    int status = run_program(argv, message, sizeof message);
    if (status != 0) {
        sk_atomic_file_abort(&f);
        if (status < 0) return sk_fail(err, SK_ERROR_IO, "%s: could not run %s", path, ffmpeg);
        return sk_fail(err, SK_ERROR_IO, "%s: %s exited with status %d%s%s", path, ffmpeg, status,
                       message[0] ? ": " : "", message);
    }
    r = sk_atomic_file_commit(&f, err);
    *written = r == SK_OK;
    return r;
}
