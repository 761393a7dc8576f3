/* Tests of the `shitsukan` command's framework: help, version, exit codes and one-line
 * errors for bad usage. Module commands have their own tests in their modules' files. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "test_support.h"

#include "shitsukan/hand.h"

static sk_test_run g_run;

/* A path under the test folder with nothing there yet. */
static const char *fresh_path(const char *name)
{
    const char *path = sk_test_path(name);
    char command[2048];
    snprintf(command, sizeof command, "rm -rf '%s'", path);
    assert_int_equal(system(command), 0);
    return path;
}

static void assert_one_line_error(const sk_test_run *run, int status)
{
    assert_int_equal(run->status, status);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_true(strncmp(run->err, "shitsukan: error: ", 18) == 0);
}

static void test_version_and_help(void **state)
{
    (void)state;
    assert_int_equal(sk_test_cli(&g_run, "--version"), 0);
    assert_true(strncmp(g_run.out, "shitsukan ", 10) == 0);
    assert_int_equal(sk_test_cli(&g_run, "--help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan <command>"));
    assert_non_null(strstr(g_run.out, "presets"));
    assert_int_equal(sk_test_cli(&g_run, "presets --help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan presets"));
    assert_string_equal(g_run.err, "");
}

static void test_bad_usage_exits_2_with_one_line(void **state)
{
    (void)state;
    sk_test_cli(&g_run, "%s", "");
    assert_int_equal(g_run.status, 2);
    sk_test_cli(&g_run, "no-such-command");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "unknown command 'no-such-command'"));
    sk_test_cli(&g_run, "presets --no-such-option");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "unknown option '--no-such-option'"));
    sk_test_cli(&g_run, "presets a b c");
    assert_one_line_error(&g_run, 2);
    sk_test_cli(&g_run, "presets no-such-module");
    assert_one_line_error(&g_run, 2);
    sk_test_cli(&g_run, "presets no-such-module no-such-preset");
    assert_one_line_error(&g_run, 2);
}

/* "shitsukan hand --help" and "shitsukan hand" said "unknown command 'hand'". */
static void test_groups_have_help(void **state)
{
    (void)state;
    static const char *const groups[] = {"hand", "wood", "tissue"};
    for (size_t i = 0; i < sizeof groups / sizeof groups[0]; i++) {
        assert_int_equal(sk_test_cli(&g_run, "%s --help", groups[i]), 0);
        assert_non_null(strstr(g_run.out, "subcommands:"));
        assert_string_equal(g_run.err, "");
        sk_test_cli(&g_run, "%s", groups[i]);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "needs a subcommand"));
        sk_test_cli(&g_run, "%s no-such-subcommand", groups[i]);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "unknown command"));
    }
    assert_int_equal(sk_test_cli(&g_run, "hand --help"), 0);
    assert_non_null(strstr(g_run.out, "  hand pose "));
    assert_non_null(strstr(g_run.out, "  hand calibrate "));
    /* a command that is also a group lists its subcommands under its own help */
    assert_int_equal(sk_test_cli(&g_run, "skin --help"), 0);
    assert_non_null(strstr(g_run.out, "usage: shitsukan skin [options]"));
    assert_non_null(strstr(g_run.out, "  skin maps "));
}

/* --region sums overflowed a signed integer (0,0,4,4 ran for huge x, w). */
static void test_region_cannot_overflow(void **state)
{
    (void)state;
    const char *out = fresh_path("region.png");
    static const char *const regions[] = {
        "4611686018427387904,0,6917529027641081860,4",
        "9223372036854775807,0,1,1",
        "0,0,9223372036854775807,1",
        "1,1,-9223372036854775807,1",
        "0,0,99999999999999999999,1",
        "0x1,0,1,1",
        " 1,0,1,1",
        "1,0,1,1,",
    };
    for (size_t i = 0; i < sizeof regions / sizeof regions[0]; i++) {
        sk_test_cli(&g_run, "noise --size 16 -q --region '%s' -o '%s'", regions[i], out);
        assert_one_line_error(&g_run, 2);
        assert_non_null(strstr(g_run.err, "--region"));
        assert_false(sk_test_file_exists(out));
    }
    assert_int_equal(sk_test_cli(&g_run, "noise --size 16 -q --region 12,0,4,16 -o '%s'", out), 0);
    assert_true(sk_test_file_exists(out));
}

/* --pin: hexadecimal accepted as a number, 1e30 refused without the limit, the 65th
 * silently dropped, a repeated DOF silently keeping the last, a pin and a torque on one DOF
 * both accepted. */
static void test_hand_inputs_are_checked(void **state)
{
    (void)state;
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=0x3c");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "[-1000000, 1000000]"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=1e30");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "[-1000000, 1000000]"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=10 --pin L.MCP.flex=20");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "L.MCP.flex already has --pin"));
    sk_test_cli(&g_run, "hand pose --pin L.MCP.flex=10 --torque L.MCP.flex=0.5");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "L.MCP.flex already has --pin"));
    /* 65 distinct inputs: every one is honoured (the hand has 49 DOFs, so 65 must repeat
       one; the repeat is named, not dropped) */
    char many[8192];
    size_t used = 0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        used += (size_t)snprintf(many + used, sizeof many - used, " --torque %s=0.01",
                                 sk_hand_dof(i)->name);
    assert_int_equal(sk_test_cli(&g_run, "hand pose%s", many), 0);
    for (int i = 0; i < 65 - SK_HAND_DOF_COUNT; i++)
        used +=
            (size_t)snprintf(many + used, sizeof many - used, " --pin %s=1", sk_hand_dof(i)->name);
    sk_test_cli(&g_run, "hand pose%s", many);
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "already has --pin"));
}

/* ------------------------------------------------------------ bad input sweep */

/* One bad invocation: the arguments (OUT is replaced by a fresh output path, DIR by a
 * fresh folder holding a file "file", a folder "folder.png" and small inputs), and two
 * texts the one-line message must hold (the option or key, and its accepted range). */
typedef struct bad_case {
    const char *args;
    const char *names, *range;
} bad_case;

static const bad_case k_bad_cases[] = {
    /* presets */
    {"presets no-such-module", "no-such-module", "skin"},
    /* noise */
    {"noise --size 0 -o OUT.png", "--size", "[1, 65536]"},
    {"noise --size 70000 -o OUT.png", "--size", "[1, 65536]"},
    {"noise --size 8x -o OUT.png", "--size", "WxH"},
    {"noise --bits 12 -o OUT.png", "--bits", "8 or 16"},
    {"noise --bits x -o OUT.png", "--bits", "[8, 16]"},
    {"noise --region 0,0,9,9 --size 8 -o OUT.png", "--region", "x + w <= 8"},
    {"noise --seed -1 -o OUT.png", "--seed", "[0, 2^53]"},
    {"noise --seed 9007199254740993 -o OUT.png", "--seed", "[0, 2^53]"},
    {"noise --threads 5000 -o OUT.png", "--threads", "[0, 1024]"},
    {"noise --set cells=0 -o OUT.png", "cells", "out of range"},
    {"noise --set cells=5junk -o OUT.png", "cells", "expected a number"},
    {"noise --set seamless=truex -o OUT.png", "seamless", "true or false"},
    {"noise --set nosuchkey=1 -o OUT.png", "nosuchkey", "unknown key"},
    {"noise --preset no-such-preset -o OUT.png", "--preset", "shitsukan presets noise"},
    {"noise --size 8 -o OUT.jpg", "OUT.jpg", ".png, .exr"},
    {"noise --max-memory 1K -o OUT.png", "--max-memory", "[1M, 1P]"},
    {"noise --size 20000 --max-memory 512M -o OUT.png", "--size", "--max-memory"},
    {"noise --size 65536 --max-memory 1P -o OUT.png", "--size", "an image may hold"},
    {"noise --size 8 -o DIR/folder.png", "folder.png", "folder"},
    /* sheet */
    {"sheet --columns -1 DIR/a.png -o OUT.png", "--columns", "[0, 4096]"},
    {"sheet --tile-size 20000 DIR/a.png -o OUT.png", "--tile-size", "[0, 16384]"},
    {"sheet --tile-size 16384 DIR/a.png DIR/a.png -o OUT.png", "--tile-size", "--max-memory"},
    {"sheet --text-scale 0 DIR/a.png -o OUT.png", "--text-scale", "[1, 64]"},
    {"sheet --border 65 DIR/a.png -o OUT.png", "--border", "[0, 64]"},
    {"sheet --repeat 0x2 DIR/a.png -o OUT.png", "--repeat", "[1, 64]"},
    {"sheet --repeat 2x2 DIR/a.png DIR/a.png -o OUT.png", "--repeat", "exactly one image"},
    {"sheet --label a --label b DIR/a.png -o OUT.png", "labels", "1 images"},
    {"sheet DIR/no-such.png -o OUT.png", "no-such.png", "cannot open"},
    {"sheet DIR/folder.png -o OUT.png", "folder.png", "not a regular file"},
    {"sheet DIR/file -o OUT.png", "file", "not a PNG"},
    {"sheet DIR/a.png -o OUT.gif", "OUT.gif", ".png, .exr"},
    /* hand pose */
    {"hand pose --pin L.MCP.flex -o OUT.json", "--pin", "DOF=value"},
    {"hand pose --pin X.MCP.flex=1 -o OUT.json", "--pin", "unknown DOF"},
    {"hand pose --torque L.MCP.flex=nan -o OUT.json", "--torque", "[-1000000, 1000000]"},
    {"hand pose --constraints no-such -o OUT.json", "--constraints", "natural, yasumuro-table-3.2"},
    {"hand pose --samples DIR/s.csv -o OUT.json", "--samples", "--pairs"},
    {"hand pose --samples DIR/s.csv --pairs L.MCP.flex:R.MCP.flex --lut-resolution 2 -o OUT.json",
     "--lut-resolution", "[8, 1024]"},
    {"hand pose --samples DIR/s.csv --pairs L.MCP.flex:R.MCP.flex --lut-weight 0 -o OUT.json",
     "--lut-weight", "[1e-06, 1e+06]"},
    {"hand pose --samples DIR/s.csv --pairs L.MCP.flex:R.MCP.flex --lut-interp cubic -o OUT.json",
     "--lut-interp", "hermite or bilinear"},
    {"hand pose --side up -o OUT.json", "--side", "right or left"},
    {"hand pose --hand-length 10 -o OUT.json", "--hand-length", "[60, 400]"},
    {"hand pose --hand-breadth 1000 -o OUT.json", "--hand-breadth", "[30, 200]"},
    {"hand pose --anatomy DIR/no-such.json -o OUT.json", "no-such.json", "cannot open"},
    {"hand pose --anatomy DIR/folder.png -o OUT.json", "folder.png", "not a regular file"},
    {"hand pose --png OUT.png --views top", "--views", "dorsal, palmar, radial, ulnar"},
    {"hand pose --png OUT.png --png-size 10", "--png-size", "at least 64"},
    {"hand pose --png OUT.jpg", "--png", ".png"},
    {"hand pose --positions OUT.txt", "--positions", ".csv, .json"},
    {"hand pose --views dorsal -o OUT.json", "--views", "--png"},
    {"hand pose --bvh OUT.json --positions OUT.json", "OUT.json", "given twice"},
    /* hand animate */
    {"hand animate DIR/no-such.json --bvh OUT.bvh", "no-such.json", "cannot open"},
    {"hand animate DIR/anim.json", "nothing to write", "--bvh"},
    {"hand animate DIR/anim.json --bvh OUT.bvh --side up", "--side", "right or left"},
    {"hand animate DIR/anim.json --bvh OUT.bvh --hand-length 1", "--hand-length", "[60, 400]"},
    {"hand animate DIR/anim.json --bvh OUT.bvh --constraints nope", "--constraints", "natural"},
    {"hand animate DIR/anim.json --frames-dir OUT --png-size 8", "--png-size", "at least 64"},
    {"hand animate DIR/anim.json --frames-dir DIR/file", "file", "not a folder"},
    {"hand animate DIR/anim.json --plot OUT.jpg", "--plot", ".png"},
    {"hand animate DIR/anim.json --plot OUT.png --plot-size 10", "--plot-size", "at least 64"},
    {"hand animate DIR/anim.json --plot OUT.png --plot-dofs X.Y", "--plot-dofs", "unknown DOF"},
    {"hand animate DIR/long-anim.json --bvh OUT.bvh --max-memory 1M", "10001 frames",
     "--max-memory"},
    {"hand animate DIR/garbage.json --bvh OUT.bvh", "garbage.json", "unexpected text"},
    {"hand animate DIR/anim.json --glb OUT.gltf", "--glb", ".glb"},
    {"hand animate DIR/anim.json --landmarks OUT.txt", "--landmarks", ".csv, .json"},
    {"hand animate DIR/anim.json --meshes-dir DIR/file", "file", "not a folder"},
    {"hand animate DIR/anim.json --meshes-dir OUT --mesh-frames 99", "--mesh-frames",
     "comma-separated"},
    {"hand animate DIR/anim.json --meshes-dir OUT --mesh-frames 0,", "--mesh-frames",
     "comma-separated"},
    {"hand animate DIR/anim.json --bvh OUT.bvh --mesh-frames 0", "--mesh-frames",
     "needs --meshes-dir"},
    {"hand animate DIR/anim.json --bvh OUT.bvh --skinning lbs", "--skinning", "needs --glb"},
    {"hand animate DIR/anim.json --glb OUT.glb --texture OUT", "--texture", "needs --meshes-dir"},
    {"hand animate DIR/anim.json --glb OUT.glb --material wax", "--material", "blend or pbr"},
    {"hand animate DIR/anim.json --glb OUT.glb --skinning soft", "--skinning", "rigid, lbs or dqs"},
    {"hand animate DIR/anim.json --glb OUT.glb --texture-size 32", "--texture-size", "[64, 8192]"},
    {"hand animate DIR/anim.json --glb OUT.glb --triangles 200000 --max-memory 64M", "--triangles",
     "--max-memory"},
    {"hand animate DIR/anim.json --meshes-dir OUT --flesh DIR/garbage.json", "garbage.json",
     "unexpected text"},
    /* hand mesh */
    {"hand mesh", "-o", ".glb"},
    {"hand mesh -o OUT.stl", "-o", ".obj, .ply, .glb"},
    {"hand mesh -o DIR/folder.glb", "folder.glb", "names a folder"},
    {"hand mesh --pin L.MCP.flex=0x3c -o OUT.obj", "--pin", "[-1000000, 1000000]"},
    {"hand mesh --pin L.MCP.flex=1 --pin L.MCP.flex=2 -o OUT.obj", "L.MCP.flex",
     "already has --pin"},
    {"hand mesh --pin L.MCP.flex=1 --pose DIR/pose.json -o OUT.obj", "--pose", "--pin"},
    {"hand mesh --pose DIR/garbage.json -o OUT.obj", "garbage.json", "unexpected text"},
    {"hand mesh --pose DIR/folder.png -o OUT.obj", "folder.png", "not a regular file"},
    {"hand mesh --flesh DIR/garbage.json -o OUT.obj", "garbage.json", "unexpected text"},
    {"hand mesh --triangles 100 -o OUT.obj", "--triangles", "[500, 200000]"},
    {"hand mesh --lod 3 -o OUT.obj", "--lod", "[0, 2]"},
    {"hand mesh --skinning soft -o OUT.obj", "--skinning", "rigid, lbs or dqs"},
    {"hand mesh --material wax -o OUT.glb", "--material", "blend or pbr"},
    {"hand mesh --material pbr -o OUT.obj", "--material", ".glb"},
    {"hand mesh --texture OUT -o OUT.glb", "--texture", ".glb"},
    {"hand mesh --texture-size 64 -o OUT.obj", "--texture-size", "--texture"},
    {"hand mesh --texture OUT -o /dev/null", "--texture", "device or FIFO"},
    {"hand mesh --texture OUT --texture-size 10 -o OUT.obj", "--texture-size", "[64, 8192]"},
    {"hand mesh --constraints nope -o OUT.obj", "--constraints", "natural"},
    {"hand mesh --potential DIR/garbage.json -o OUT.obj", "garbage.json", "unexpected text"},
    {"hand mesh --potential DIR/garbage.json --constraints natural -o OUT.obj", "--potential",
     "--constraints"},
    {"hand mesh --triangles 200000 --max-memory 64M -o OUT.glb", "--triangles", "--max-memory"},
    /* hand scan */
    {"hand scan", "-o", "is required"},
    {"hand scan -o DIR/file", "file", "not a folder"},
    {"hand scan --lines 8 -o OUT", "--lines", "[75, 4096]"},
    {"hand scan --points 5000 -o OUT", "--points", "[60, 4096]"},
    {"hand scan --slices 1 -o OUT", "--slices", "[2, 2000]"},
    {"hand scan --noise -1 -o OUT", "--noise", "[0, 10]"},
    {"hand scan --pin I.MCP.flex=0x10 -o OUT", "--pin", "[-1000000, 1000000]"},
    {"hand scan --pin I.MCP.flex=1 --pin I.MCP.flex=2 -o OUT", "I.MCP.flex", "already has --pin"},
    {"hand scan --bend I.MCP.flex=1 --bend I.MCP.flex=2 -o OUT", "I.MCP.flex",
     "already has --bend"},
    {"hand scan --bend X.MCP.flex=1 -o OUT", "--bend", "unknown DOF"},
    {"hand scan --bend I.MCP.flex=1 --no-pictures -o OUT", "--bend", "--no-pictures"},
    {"hand scan --pose DIR/garbage.json -o OUT", "garbage.json", "unexpected text"},
    {"hand scan --input DIR/folder.png -o OUT", "folder.png", ".obj, .ply"},
    {"hand scan --input DIR/no-such.ply -o OUT", "no-such.ply", "cannot open"},
    {"hand scan --lines 4096 --points 4096 --max-memory 1G -o OUT", "--lines x --points",
     "--max-memory"},
    /* tissue */
    {"tissue skin --character nobody -o OUT.obj", "--character", "arm, body"},
    {"tissue skin --character DIR/garbage.json -o OUT.obj", "garbage.json", "unexpected text"},
    {"tissue skin --character arm -o OUT.stl", "-o", ".obj, .ply"},
    {"tissue skin --character arm -o OUT.obj --stats OUT.txt", "--stats", ".json"},
    {"tissue skin --character arm --layers DIR/file", "file", "not a folder"},
    {"tissue skin --character arm --set skin.spacing_mm=nan -o OUT.obj", "skin.spacing_mm",
     "[0, 50]"},
    {"tissue skin --character arm --set skin.spacing_mm=1 --max-memory 512M -o OUT.obj",
     "skin.spacing_mm", "--max-memory"},
    {"tissue skin --character arm", "nothing to write", "--layers"},
    {"tissue run --character arm --motion curl -o DIR/file", "file", "not a folder"},
    {"tissue run --character arm --motion curl --plot OUT.jpg -o OUT", "--plot", ".png"},
    {"tissue run --character arm --motion curl --fps 0 -o OUT", "--fps", "[1, 1000]"},
    {"tissue run --character arm --motion curl --frames 5:2 -o OUT", "--frames", "A:B"},
    {"tissue run --character arm --motion curl --render-width 10 -o OUT", "--render-width",
     "[64, 4096]"},
    {"tissue run --character arm --motion DIR/no-such.bvh -o OUT", "no-such.bvh", "cannot open"},
    {"tissue run --character arm --motion dance -o OUT", "--motion", "curl, jump, walk"},
    {"tissue run --character arm --set skin.spacing_mm=10 --set skin.dilation_radius_mm=15 "
     "--motion curl "
     "--resume DIR/file -o OUT",
     "file", "SKTSTATE"},
    {"tissue motion dance -o OUT.bvh", "dance", "curl, jump or walk"},
    {"tissue motion curl -o OUT.txt", "-o", ".bvh"},
    /* showcase */
    {"showcase --melody DIR/melody.txt --max-memory 64M -o OUT", "--hand-triangles",
     "--max-memory"},
    {"showcase --melody DIR/melody.txt --spp 0 -o OUT", "--spp", "[1, 1024]"},
    {"showcase midi --melody DIR/melody.txt -o OUT.jpg", "-o", ".mid"},
    {"showcase midi --melody DIR/bad-note.txt -o OUT.mid", "bad-note.txt:2", "key number 21..108"},
    {"showcase --melody DIR/melody.txt --frames 5:2 -o OUT", "--frames", "A <= B"},
    {"showcase --melody DIR/melody.txt --frames 0:99999 -o OUT", "--frames", "frames 0:"},
    {"showcase --melody DIR/melody.txt --fps nan -o OUT", "--fps", "[1, 240]"},
    {"showcase --melody DIR/melody.txt --size 99999x2 -o OUT", "--size", "[1, 8192]"},
    {"showcase --melody DIR/melody.txt --size 8x8 -o OUT", "--size", "at least 16x16"},
    {"showcase --melody DIR/melody.txt --duration -1 -o OUT", "--duration", "[0.001, 3600]"},
    {"showcase --melody DIR/melody.txt --texture-size 3 -o OUT", "--texture-size", "[64, 8192]"},
    {"showcase --melody DIR/melody.txt --hand-triangles 10 -o OUT", "--hand-triangles",
     "[500, 200000]"},
    {"showcase --melody DIR/melody.txt --forearm nobody -o OUT", "--forearm", "no such preset"},
    {"showcase --melody DIR/melody.txt --forearm DIR/garbage.json -o OUT", "garbage.json",
     "unexpected text"},
    {"showcase --melody DIR/melody.txt --constraints nobody -o OUT", "--constraints",
     "no such preset"},
    {"showcase --melody DIR/melody.txt --set film.exposure=99 -o OUT", "film.exposure",
     "[-30, 30]"},
    {"showcase --melody DIR/melody.txt --ffmpeg DIR/no-such-ffmpeg -o OUT", "no-such-ffmpeg",
     "--no-video"},
    {"showcase --melody DIR/melody.txt -o DIR/file", "file", "not a folder"},
    {"showcase --melody DIR/bad-note.txt -o OUT", "bad-note.txt:2", "key number 21..108"},
    {"showcase --melody DIR/bad.mid -o OUT", "bad.mid: byte 0", "MThd"},
    {"showcase --melody DIR/folder.png -o OUT", "folder.png", "not a regular file"},
    {"showcase --melody DIR/no-such.txt -o OUT", "no-such.txt", "cannot open"},
    /* studio */
    {"studio --port 70000", "--port", "[0, 65535]"},
    {"studio --port x", "--port", "[0, 65535]"},
    {"studio --host nowhere", "--host", "IPv4"},
    {"studio --root DIR/file", "--root", "must be a folder"},
    {"studio --root DIR", "--root", "no index.html"},
    /* hand calibrate */
    /* the choices of an option that sets a key are its schema's names, in their order */
    {"hand calibrate DIR/s.csv --method x -o OUT.json", "--method", "gaussian, mixture or pairs"},
    /* hand evaluate, hand synthesize */
    {"hand evaluate DIR/s.csv --pins L.MCP.flex --folds 0", "--folds", "[2, 1000]"},
    {"hand evaluate DIR/s.csv --pins L.MCP.flex --units furlongs", "--units", "rad or deg"},
    {"hand evaluate DIR/s.csv --pins L.MCP.flex --plot OUT.jpg", "--plot", ".png"},
    {"hand evaluate DIR/s.csv --pins L.MCP.flex --report OUT.txt", "--report", ".json"},
    {"hand synthesize -o OUT.csv --people 0", "--people", "[1, 100]"},
    {"hand synthesize -o OUT.csv --noise -1", "--noise", "[0, 20]"},
    {"hand calibrate DIR/s.csv --pairs L.MCP.flex -o OUT.json", "--pairs", "DOF:DOF"},
    {"hand calibrate DIR/s.csv --pairs L.MCP.flex:R.MCP.flex --weights x -o OUT.json", "--weights",
     "thesis or inverse-variance"},
    {"hand calibrate DIR/huge.csv --pairs L.MCP.flex:R.MCP.flex -o OUT.json", "L.MCP.flex",
     "[-1e6, 1e6]"},
    {"hand calibrate DIR/folder.png --pairs L.MCP.flex:R.MCP.flex -o OUT.json", "folder.png",
     "not a regular file"},
    /* skin */
    {"skin --size 0 -o OUT.png", "--size", "[1, 65536]"},
    {"skin --mm-per-px 0 -o OUT.png", "--mm-per-px", "[1e-06, 100]"},
    {"skin --size 8 --region 0,0,8,9 -o OUT.png", "--region", "y + h <= 8"},
    {"skin --samples 9 -o OUT.png", "--samples", "[1, 8]"},
    {"skin --set levels[0].spacing_mm=-1 -o OUT.png", "levels[0].spacing_mm", "out of range"},
    {"skin --set size_mm=[300,300] --size 16 -o OUT.png", "size_mm", "memory cap"},
    {"skin -o OUT.jpg", "OUT.jpg", ".png"},
    /* skin maps */
    {"skin maps --size 70000 -o OUT", "--size", "[1, 65536]"},
    {"skin maps --size 8 --furrow-level 9 -o OUT", "--furrow-level", "[1, 6]"},
    {"skin maps --size 8 --id-level 0 -o OUT", "--id-level", "[1, 6]"},
    {"skin maps --size 8 --furrow-level 3 --preset fig13a -o OUT", "--furrow-level", "at most 1"},
    {"skin maps --size 8 --samples 0 -o OUT", "--samples", "[1, 8]"},
    {"skin maps --size 8 -o DIR/file", "file", "not a folder"},
    {"skin maps --size 20000 -o OUT", "--size", "--max-memory"},
    {"skin --size 65536 --max-memory 1P -o OUT.png", "--size", "an image may hold"},
    /* wood cut */
    {"wood cut --plane diagonal -o OUT.png", "--plane", "end, flat or quarter"},
    {"wood cut --distance -1 -o OUT.png", "--distance", "[0, 10000]"},
    {"wood cut --height 1e9 -o OUT.png", "--height", "[-100000, 100000]"},
    {"wood cut --width-mm 0 -o OUT.png", "--width-mm", "[0.01, 100000]"},
    {"wood cut --tilt 100 -o OUT.png", "--tilt", "[-90, 90]"},
    {"wood cut --view-deg 90 -o OUT.png", "--view-deg", "[-89, 89]"},
    {"wood cut --light-deg 0x10 -o OUT.png", "--light-deg", "[-89, 89]"},
    {"wood cut --light-azimuth 200 -o OUT.png", "--light-azimuth", "[-180, 180]"},
    {"wood cut --samples 9 -o OUT.png", "--samples", "[1, 8]"},
    {"wood cut --point 1,2 --normal 0,0,1 --axis 1,0,0 -o OUT.png", "--point", "3 comma-separated"},
    {"wood cut --point 1,2,3 -o OUT.png", "--point", "--normal and --axis"},
    {"wood cut --size 8 --region 8,0,1,1 -o OUT.png", "--region", "x + w <= 8"},
    {"wood cut --size 20000 --maps OUT -o DIR/cut.png", "--size", "--max-memory"},
    {"wood cut --size 8 --maps DIR/file -o OUT.png", "file", "not a folder"},
    {"wood cut --set rings.width_mm=99 -o OUT.png", "rings.width_mm", "out of range"},
    {"wood cut -o OUT.bmp", "OUT.bmp", ".png, .exr"},
    /* wood sweep */
    {"wood sweep --frames 1 -o OUT", "--frames", "[2, 10000]"},
    {"wood sweep --from-deg 100 -o OUT", "--from-deg", "[-89, 89]"},
    {"wood sweep --to-deg -100 -o OUT", "--to-deg", "[-89, 89]"},
    {"wood sweep --size 8 -o DIR/file", "file", "not a folder"},
    {"wood sweep --size 25000 -o OUT", "--size", "--max-memory"},
    /* render */
    {"render DIR/scene.json --size 0x0 -o OUT.png", "--size", "[1, 16384]"},
    {"render DIR/scene.json --spp 0 -o OUT.png", "--spp", "[1, 4096]"},
    {"render DIR/scene.json --exposure 99 -o OUT.png", "--exposure", "[-30, 30]"},
    {"render DIR/scene.json --exr OUT.png -o DIR/render.png", "--exr", ".exr"},
    {"render DIR/scene.json -o OUT.jpg", "OUT.jpg", ".png, .exr"},
    {"render DIR/no-such.json -o OUT.png", "no-such.json", "cannot open"},
    {"render DIR/scene.json --set image.width=0 -o OUT.png", "image.width", "out of range"},
    {"render DIR/scene.json --set objects[0].segments=4096 --set objects[0].rings=4096 "
     "--max-memory 64M -o OUT.png",
     "objects[0]", "--max-memory"},
    {"render DIR/scene.json --set unit_mm=1e-7 -o OUT.png", "unit_mm", "[1e-06, 1e+09]"},
    {"render DIR/scene.json --export OUT.stl", "--export", ".glb, .obj"},
    {"render DIR/scene.json --texture-size 64 -o OUT.png", "--texture-size", "--export"},
    {"render DIR/scene.json --export OUT.glb --texture-size 8", "--texture-size", "[16, 8192]"},
    {"render DIR/scene.json --export OUT.glb --exr OUT.exr", "--exr", "needs -o"},
    {"render DIR/scene.json --export DIR/folder.glb -o OUT.png", "--export", "names a folder"},
    {"render DIR/wood-scene.json --export OUT.glb --texture-size 8192 --max-memory 256M",
     "--texture-size", "--max-memory"},
};

/* Small inputs of every kind the commands read. */
static void make_inputs(const char *dir)
{
    char path[2048];
    snprintf(path, sizeof path, "%s/file", dir);
    sk_test_write_file(path, "not an image\n", 13);
    snprintf(path, sizeof path, "mkdir -p '%s/folder.png' '%s/folder.glb'", dir, dir);
    assert_int_equal(system(path), 0);
    snprintf(path, sizeof path, "%s/a.png", dir);
    assert_int_equal(sk_test_cli(&g_run, "noise --size 8 -q -o '%s'", path), 0);
    snprintf(path, sizeof path, "%s/s.csv", dir);
    const char *csv = "L.MCP.flex,R.MCP.flex\n10,12\n20,25\n30,33\n40,41\n";
    sk_test_write_file(path, csv, strlen(csv));
    snprintf(path, sizeof path, "%s/huge.csv", dir);
    const char *huge = "L.MCP.flex,R.MCP.flex\n1e308,12\n20,25\n30,1e308\n";
    sk_test_write_file(path, huge, strlen(huge));
    snprintf(path, sizeof path, "%s/anim.json", dir);
    const char *anim = "{\"steps\": 2, \"keys\": [{\"pin\": {\"L.MCP.flex\": 0}}, "
                       "{\"pin\": {\"L.MCP.flex\": 60}}]}";
    sk_test_write_file(path, anim, strlen(anim));
    snprintf(path, sizeof path, "%s/long-anim.json", dir);
    const char *long_anim = "{\"steps\": 10000, \"keys\": [{\"pin\": {\"L.MCP.flex\": 0}}, "
                            "{\"pin\": {\"L.MCP.flex\": 60}}]}";
    sk_test_write_file(path, long_anim, strlen(long_anim));
    snprintf(path, sizeof path, "%s/garbage.json", dir);
    const char *garbage = "{\"keys\": [{\"pin\": {\"L.MCP.flex\": 0}}]} trailing";
    sk_test_write_file(path, garbage, strlen(garbage));
    snprintf(path, sizeof path, "%s/scene.json", dir);
    const char *scene = "{\"image\": {\"width\": 8, \"height\": 8, \"samples\": 1}, "
                        "\"objects\": [{\"shape\": \"sphere\"}]}";
    sk_test_write_file(path, scene, strlen(scene));
    snprintf(path, sizeof path, "%s/wood-scene.json", dir);
    const char *wood =
        "{\"image\": {\"width\": 8, \"height\": 8, \"samples\": 1}, \"materials\": [{\"name\": "
        "\"oak\", \"type\": \"wood\", \"wood_preset\": \"oak\"}], \"objects\": [{\"shape\": "
        "\"sphere\", \"material\": \"oak\"}]}";
    sk_test_write_file(path, wood, strlen(wood));
    snprintf(path, sizeof path, "%s/melody.txt", dir);
    const char *melody = "C4 0 0.5\nE4 0.5 0.5\n";
    sk_test_write_file(path, melody, strlen(melody));
    snprintf(path, sizeof path, "%s/bad-note.txt", dir);
    const char *bad_note = "C4 0 0.5\nQ9 0.5 0.5\n";
    sk_test_write_file(path, bad_note, strlen(bad_note));
    snprintf(path, sizeof path, "%s/bad.mid", dir);
    sk_test_write_file(path, "MThd\0\0\0\6\0\0\0\1\0", 13);
}

/* Replaces OUT and DIR in `text`. */
static void expand(const char *text, const char *out, const char *dir, char *buf, size_t size)
{
    size_t used = 0;
    for (const char *p = text; *p && used + 1 < size;) {
        const char *with = NULL;
        size_t skip = 0;
        if (strncmp(p, "OUT", 3) == 0)
            with = out, skip = 3;
        else if (strncmp(p, "DIR", 3) == 0)
            with = dir, skip = 3;
        if (with) {
            used += (size_t)snprintf(buf + used, size - used, "%s", with);
            p += skip;
        } else {
            buf[used++] = *p++;
        }
    }
    buf[used < size ? used : size - 1] = '\0';
}

/* The hand commands' and the showcase's options are other names for preset keys: an
 * option, its key by --set and the key in a preset file give the same output; a --set
 * after the option wins; --help-keys lists the keys. */
static void test_options_are_preset_keys(void **state)
{
    (void)state;
    const char *a = fresh_path("keys-a.csv"), *b = fresh_path("keys-b.csv");
    const char *c = fresh_path("keys-c.csv"), *d = fresh_path("keys-d.csv");
    const char *preset = fresh_path("keys.json");
    static const char text[] = "{\"synthetic\": {\"people\": 2, \"trials\": 1, \"frames\": 5}}";
    sk_test_write_file(preset, text, sizeof text - 1);
    assert_int_equal(sk_test_cli(&g_run,
                                 "hand synthesize --people 2 --trials 1 --frames 5 "
                                 "--noise 0 --seed 3 -o '%s'",
                                 a),
                     0);
    assert_int_equal(
        sk_test_cli(&g_run,
                    "hand synthesize --set synthetic.people=2 --set synthetic.trials=1 "
                    "--set synthetic.frames=5 --set synthetic.noise_deg=-1 --set "
                    "synthetic.seed=3 -o '%s'",
                    b),
        0);
    assert_int_equal(
        sk_test_cli(&g_run, "hand synthesize --preset '%s' --noise 0 --seed 3 -o '%s'", preset, c),
        0);
    assert_int_equal(sk_test_cli(&g_run,
                                 "hand synthesize --people 4 --trials 1 --frames 5 --noise 0 "
                                 "--seed 3 --set synthetic.people=2 -o '%s'",
                                 d),
                     0);
    assert_true(sk_test_same_file(a, b));
    assert_true(sk_test_same_file(a, c));
    assert_true(sk_test_same_file(a, d));
    const char *p1 = fresh_path("keys-pose1.json"), *p2 = fresh_path("keys-pose2.json");
    assert_int_equal(sk_test_cli(&g_run, "hand pose --side left --hand-length 170 -o '%s'", p1), 0);
    assert_int_equal(sk_test_cli(&g_run,
                                 "hand pose --set hand.side=left --set hand.hand_length_mm=170 "
                                 "-o '%s'",
                                 p2),
                     0);
    assert_true(sk_test_same_file(p1, p2));
    sk_test_cli(&g_run, "hand pose --set hand.sid=left");
    assert_one_line_error(&g_run, 2);
    assert_non_null(strstr(g_run.err, "hand.sid: unknown key (did you mean 'side'?)"));
    assert_int_equal(sk_test_cli(&g_run, "hand scan --help-keys"), 0);
    assert_non_null(strstr(g_run.out, "scan.scanner.lines"));
    assert_int_equal(sk_test_cli(&g_run, "showcase --help-keys"), 0);
    assert_non_null(strstr(g_run.out, "showcase.fps"));
    assert_non_null(strstr(g_run.out, "camera.fov_deg"));
}

/* Every command: a bad value of each kind of option exits 2 with one line naming the
 * option or key and what it accepts, and writes nothing. */
static void test_every_command_refuses_bad_input(void **state)
{
    (void)state;
    const char *dir = fresh_path("bad-input");
    char command[2048];
    snprintf(command, sizeof command, "mkdir -p '%s'", dir);
    assert_int_equal(system(command), 0);
    make_inputs(dir);
    char out[1024];
    snprintf(out, sizeof out, "%s/out", dir);
    int failures = 0;
    for (size_t i = 0; i < sizeof k_bad_cases / sizeof k_bad_cases[0]; i++) {
        const bad_case *c = &k_bad_cases[i];
        char args[2048], names[1024], range[1024];
        expand(c->args, out, dir, args, sizeof args);
        expand(c->names, out, dir, names, sizeof names);
        expand(c->range, out, dir, range, sizeof range);
        sk_test_cli(&g_run, "%s", args);
        bool ok = g_run.status == 2 && sk_test_count_lines(g_run.err) == 1 &&
                  strncmp(g_run.err, "shitsukan: error: ", 18) == 0 && strstr(g_run.err, names) &&
                  strstr(g_run.err, range);
        /* nothing written: no output of any name, no temporary or staged file */
        int leftovers = sk_test_count_files_containing(dir, "out") +
                        sk_test_count_files_containing(dir, ".tmp") +
                        sk_test_count_files_containing(dir, ".part") +
                        sk_test_count_files_containing(dir, "cut.png") +
                        sk_test_count_files_containing(dir, "render.png");
        if (!ok || leftovers) {
            print_error("case %zu '%s': status %d, %d leftover file(s), stderr: %s", i, args,
                        g_run.status, leftovers, g_run.err);
            failures++;
            snprintf(command, sizeof command,
                     "rm -rf '%s'/out* '%s'/.out* '%s'/cut.png '%s'/render.png", dir, dir, dir,
                     dir);
            assert_int_equal(system(command), 0);
        }
    }
    assert_int_equal(failures, 0);
}

/* Multi-file outputs were not all-or-nothing: when a later file failed the earlier ones
 * stayed; a full disk during "hand animate --positions" said only "write failed". */
static void test_outputs_are_all_or_nothing(void **state)
{
    (void)state;
    const char *dir = fresh_path("all-or-nothing");
    char command[2048], path[1024], scene[1024];
    snprintf(command, sizeof command, "mkdir -p '%s'", dir);
    assert_int_equal(system(command), 0);
    struct stat st;
    bool have_full = stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode);
    if (have_full) {
        snprintf(scene, sizeof scene, "%s/scene.json", dir);
        const char *text = "{\"image\": {\"width\": 8, \"height\": 8, \"samples\": 1}}";
        sk_test_write_file(scene, text, strlen(text));
        /* a link with the right extension onto the full device fails the second file */
        char full[1024];
        snprintf(full, sizeof full, "%s/full.exr", dir);
        assert_int_equal(symlink("/dev/full", full), 0);
        snprintf(path, sizeof path, "%s/first.png", dir);
        sk_test_cli(&g_run, "render '%s' -q -o '%s' --exr '%s'", scene, path, full);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));
        assert_false(sk_test_file_exists(path));
        /* render --export: the export's files (OBJ, MTL) go with the pictures */
        char obj[1024], mtl[1024];
        snprintf(obj, sizeof obj, "%s/export.obj", dir);
        snprintf(mtl, sizeof mtl, "%s/export.mtl", dir);
        text = "{\"image\": {\"width\": 8, \"height\": 8, \"samples\": 1}, "
               "\"objects\": [{\"shape\": \"sphere\"}]}";
        sk_test_write_file(scene, text, strlen(text));
        sk_test_cli(&g_run, "render '%s' -q --export '%s' -o '%s' --exr '%s'", scene, obj, path,
                    full);
        assert_one_line_error(&g_run, 1);
        assert_false(sk_test_file_exists(path));
        assert_false(sk_test_file_exists(obj));
        assert_false(sk_test_file_exists(mtl));
        /* and without an image, the export alone onto the full device */
        snprintf(obj, sizeof obj, "%s/full.glb", dir);
        assert_int_equal(symlink("/dev/full", obj), 0);
        sk_test_cli(&g_run, "render '%s' -q --export '%s'", scene, obj);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));

        /* hand mesh: the OBJ, its MTL and the two texture maps together (the normal map
           onto the full device) */
        char texture[1024];
        snprintf(texture, sizeof texture, "%s/full-normal.png", dir);
        assert_int_equal(symlink("/dev/full", texture), 0);
        snprintf(texture, sizeof texture, "%s/full", dir);
        snprintf(obj, sizeof obj, "%s/hand.obj", dir);
        sk_test_cli(&g_run, "hand mesh -q --triangles 500 --texture '%s' --texture-size 64 -o '%s'",
                    texture, obj);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));
        assert_false(sk_test_file_exists(obj));
        snprintf(obj, sizeof obj, "%s/hand.mtl", dir);
        assert_false(sk_test_file_exists(obj));
        snprintf(obj, sizeof obj, "%s/full-albedo.png", dir);
        assert_false(sk_test_file_exists(obj));

        snprintf(scene, sizeof scene, "%s/anim.json", dir);
        text = "{\"steps\": 3, \"keys\": [{\"pin\": {\"L.MCP.flex\": 0}}, "
               "{\"pin\": {\"L.MCP.flex\": 60}}]}";
        sk_test_write_file(scene, text, strlen(text));
        snprintf(path, sizeof path, "%s/first.bvh", dir);
        char frames[1024];
        snprintf(frames, sizeof frames, "%s/frames", dir);
        sk_test_cli(&g_run, "hand animate '%s' -q --bvh '%s' --frames-dir '%s' --angles /dev/full",
                    scene, path, frames);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));
        assert_false(sk_test_file_exists(path));
        assert_false(sk_test_file_exists(frames));
        /* hand animate's surface outputs: the landmarks and meshes go with the failed .glb */
        char glb[1024], landmarks[1024];
        snprintf(glb, sizeof glb, "%s/full.glb", dir);
        snprintf(landmarks, sizeof landmarks, "%s/landmarks.csv", dir);
        sk_test_cli(&g_run,
                    "hand animate '%s' -q --landmarks '%s' --meshes-dir '%s' --mesh-frames 0 "
                    "--triangles 500 "
                    "--texture-size 64 --glb '%s'",
                    scene, landmarks, frames, glb);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));
        assert_false(sk_test_file_exists(landmarks));
        assert_false(sk_test_file_exists(frames));
    }

    /* tissue run: the folder and the plot go with the failed saved state */
    if (have_full) {
        char run[1024], plot[1024], saved[1024];
        snprintf(run, sizeof run, "%s/tissue", dir);
        snprintf(plot, sizeof plot, "%s/tissue-plot.png", dir);
        snprintf(saved, sizeof saved, "%s/full.state", dir);
        assert_int_equal(symlink("/dev/full", saved), 0);
        sk_test_cli(
            &g_run,
            "tissue run --character arm --set skin.spacing_mm=10 --set skin.dilation_radius_mm=15 "
            "--motion curl --frames 0:2 -q -o '%s' --plot '%s' --save-state '%s'",
            run, plot, saved);
        assert_one_line_error(&g_run, 1);
        assert_non_null(strstr(g_run.err, "No space left on device"));
        assert_false(sk_test_file_exists(run));
        assert_false(sk_test_file_exists(plot));
    }

    /* hand scan: its many files appear in DIR together; one that cannot be moved into
       place (a folder of its name) takes the others back */
    char scan[1024];
    snprintf(scan, sizeof scan, "%s/scan/patches.obj", dir);
    snprintf(command, sizeof command, "mkdir -p '%s'", scan);
    assert_int_equal(system(command), 0);
    snprintf(scan, sizeof scan, "%s/scan", dir);
    sk_test_cli(&g_run, "hand scan -q --lines 75 --points 60 --slices 20 --no-pictures -o '%s'",
                scan);
    assert_one_line_error(&g_run, 1);
    assert_non_null(strstr(g_run.err, "patches.obj"));
    assert_int_equal(sk_test_count_files_containing(scan, "."), 3); /* ., .. and patches.obj */
    assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
    assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);

    /* wood cut --maps: the picture and the maps appear together */
    char maps[1024];
    snprintf(path, sizeof path, "%s/cut.png", dir);
    snprintf(maps, sizeof maps, "%s/new/maps", dir);
    assert_int_equal(sk_test_cli(&g_run, "wood cut --size 16 -q --maps '%s' -o '%s'", maps, path),
                     0);
    assert_true(sk_test_file_exists(path));
    snprintf(path, sizeof path, "%s/new/maps/pores.png", dir);
    assert_true(sk_test_file_exists(path));

    /* -o /dev/null stays a device; -o through a link keeps the link */
    assert_int_equal(sk_test_cli(&g_run, "noise --size 8 -q -o /dev/null"), 0);
    assert_int_equal(stat("/dev/null", &st), 0);
    assert_true(S_ISCHR(st.st_mode));
    char link[1024];
    snprintf(link, sizeof link, "%s/link.png", dir);
    assert_int_equal(symlink("cut.png", link), 0);
    assert_int_equal(sk_test_cli(&g_run, "noise --size 8 -q -o '%s'", link), 0);
    assert_int_equal(lstat(link, &st), 0);
    assert_true(S_ISLNK(st.st_mode));
}

static void sleep_ms(long ms)
{
    struct timespec t = {ms / 1000, (ms % 1000) * 1000000L};
    nanosleep(&t, NULL);
}

/* SIGTERM or SIGINT while "wood sweep" or "sheet" wrote left .NAME.XXXXXXXX.tmp behind. */
static void test_stopped_command_leaves_nothing(void **state)
{
    (void)state;
    static const int signals[] = {SIGTERM, SIGINT};
    for (int k = 0; k < 2; k++) {
        const char *dir = fresh_path(k ? "stopped-int" : "stopped-term");
        char command[2048], out[1024];
        snprintf(command, sizeof command, "mkdir -p '%s'", dir);
        assert_int_equal(system(command), 0);
        snprintf(out, sizeof out, "%s/sweep", dir);
        pid_t child = fork();
        assert_true(child >= 0);
        if (child == 0) {
            execl(SK_TEST_CLI, "shitsukan", "wood", "sweep", "--size", "48", "--frames", "10000",
                  "--threads", "1", "-q", "-o", out, (char *)NULL);
            _exit(127);
        }
        /* wait until frames are being written into the staged folder */
        bool writing = false;
        for (int i = 0; i < 2000 && !writing; i++) {
            sleep_ms(10);
            writing = sk_test_count_files_containing(dir, ".part") > 0;
        }
        assert_true(writing);
        sleep_ms(300);
        sk_test_kill_and_reap(child, signals[k]);
        assert_int_equal(sk_test_count_files_containing(dir, ".part"), 0);
        assert_int_equal(sk_test_count_files_containing(dir, ".tmp"), 0);
        assert_false(sk_test_file_exists(out));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_and_help),
        cmocka_unit_test(test_bad_usage_exits_2_with_one_line),
        cmocka_unit_test(test_groups_have_help),
        cmocka_unit_test(test_region_cannot_overflow),
        cmocka_unit_test(test_hand_inputs_are_checked),
        cmocka_unit_test(test_options_are_preset_keys),
        cmocka_unit_test(test_every_command_refuses_bad_input),
        cmocka_unit_test(test_outputs_are_all_or_nothing),
        cmocka_unit_test(test_stopped_command_leaves_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
