#!/usr/bin/env bash
# The models (src/models/*) neither draw nor write nor read files, nor call the thread
# runtime (threads go through the base's helpers): their libraries import no file, image,
# JSON, ray-tracing, process or OpenMP-runtime call. Usage: models_do_no_io.sh ROOT BUILD
set -euo pipefail
here=$(dirname "$0")
# OpenMP runtime calls a source may make (omp_get_thread_num and omp_get_num_threads are
# left out: gcc emits them for every statically scheduled "omp for" pragma)
runtime='omp_set_[a-z_]*|omp_get_max_threads|omp_get_num_procs|omp_in_parallel|omp_pause_[a-z_]*|omp_get_wtime|omp_[a-z_]*_lock'
io='fopen|fopen64|fdopen|freopen|open|open64|openat|creat|fwrite|fputs|fputc|fprintf|fflush'
io+='|printf|puts|putchar|rename|unlink|remove|mkdir|stat|stat64|fstat|fstat64|lstat|opendir'
io+='|read|write|pread|pwrite|mmap|mmap64'
formats='png_[a-z_]*|exr_[a-z_]*|cJSON_[A-Za-z_]*|rtc[A-Z][A-Za-z0-9]*|smf_[a-z_]*|libdeflate_[a-z_]*'
process='posix_spawn|posix_spawnp|fork|vfork|execv|execvp|execve|execl|execlp|system|popen'
exec bash "$here/module_imports.sh" "$1" "$2" models \
    "neither touch files nor start programs nor call the thread runtime" \
    "$io|$formats|$process|$runtime"
