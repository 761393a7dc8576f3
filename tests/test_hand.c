/* Tests of the hand module (thesis ch. 3): forward kinematics against hand-computed
 * positions, the equilibrium (3.17), coupling ratios, limits, mirroring, lookup-table
 * potentials, calibration (3.18), fingertip reaches through the equilibrium, keyframes,
 * BVH round trip, file errors. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shitsukan/hand.h"
#include "shitsukan/io.h"
#include "test_support.h"

#define DEG SK_DEG_TO_RAD

static sk_hand_skeleton make_skeleton(sk_hand_side side)
{
    sk_hand_skeleton s;
    sk_hand_skeleton_desc d = {0};
    d.side = side;
    sk_error err;
    assert_int_equal(sk_hand_skeleton_init(&s, &d, &err), SK_OK);
    return s;
}

static void load_constraints(const char *name, const sk_hand_skeleton *s, sk_hand_constraints *c)
{
    char path[512];
    snprintf(path, sizeof path, "%s/hand/%s.json", SK_TEST_PRESET_DIR, name);
    sk_error err = {0};
    sk_result r = sk_hand_constraints_load_file(path, s, c, &err);
    if (r != SK_OK) fprintf(stderr, "%s\n", err.message);
    assert_int_equal(r, SK_OK);
}

static sk_result parse_constraints(const char *json, const sk_hand_skeleton *s,
                                   sk_hand_constraints *c, sk_error *err)
{
    return sk_hand_constraints_parse(json, strlen(json), "test.json", s, c, err);
}

/* Random DOF values inside the limits. */
static void random_pose(const sk_hand_skeleton *s, uint64_t seed, double *q)
{
    sk_rng rng = sk_rng_make(seed, 1, 2, 3);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        double lo = s->dof[i].min, hi = s->dof[i].max;
        if (sk_hand_dof(i)->translation) lo = -50, hi = 50;
        q[i] = sk_rng_range(&rng, lo, hi);
    }
}

/* ------------------------------------------------------------ DOF table */
static void test_dof_table(void **state)
{
    (void)state;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        const sk_hand_dof_info *d = sk_hand_dof(i);
        assert_non_null(d);
        assert_int_equal(sk_hand_dof_find(d->name), i);
        int count = 0;
        /* the DOF's link lists it */
        for (int j = 0; j < SK_HAND_DOF_COUNT; j++) count += sk_hand_dof(j)->link == d->link;
        assert_true(count >= 1 && count <= 6);
        assert_true(d->sign == 1 || d->sign == -1);
    }
    assert_null(sk_hand_dof(SK_HAND_DOF_COUNT));
    assert_int_equal(sk_hand_dof_find("L.MPC.flex"), -1);
    assert_int_equal(sk_hand_dof_find("L.MCP.flex"), 31);
    /* 29 joint DOF after the 6 wrist DOF (spec decision) */
    int joint = 0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        joint += strncmp(sk_hand_dof(i)->name, "wrist", 5) != 0;
    assert_int_equal(joint, 29);
    /* every point but the wrist has a parent one step up its chain */
    for (int p = 1; p < SK_HAND_POINT_COUNT; p++) assert_true(sk_hand_point_parent(p) >= 0);
    assert_string_equal(sk_hand_link_name(17), "L_MCP");
    assert_string_equal(sk_hand_point_name(24), "L.tip");
}

/* ------------------------------------------------------------ kinematics */
static void test_euler_is_product_of_axis_rotations(void **state)
{
    (void)state;
    sk_rng rng = sk_rng_make(7, 0, 0, 0);
    for (int t = 0; t < 50; t++) {
        double x = sk_rng_range(&rng, -3, 3), y = sk_rng_range(&rng, -1.5, 1.5),
               z = sk_rng_range(&rng, -3, 3);
        sk_mat3d e = sk_hand_euler321(x, y, z);
        sk_mat3d p = sk_m3d_mul(sk_m3d_mul(sk_m3d_rot_z(z), sk_m3d_rot_y(y)), sk_m3d_rot_x(x));
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) assert_true(fabs(e.m[i][j] - p.m[i][j]) < 1e-14);
        double x2, y2, z2;
        sk_hand_euler321_from_matrix(e, &x2, &y2, &z2);
        sk_mat3d back = sk_hand_euler321(x2, y2, z2);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) assert_true(fabs(back.m[i][j] - e.m[i][j]) < 1e-12);
    }
}

static void test_forward_kinematics_hand_computed(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double hl = s.hand_length_mm;
    double q[SK_HAND_DOF_COUNT] = {0};
    sk_hand_frames f;
    /* all zero: the middle finger lies straight along +Y, one hand length to its tip */
    sk_hand_forward(&s, q, &f);
    assert_true(fabs(f.point[10].y - 0.073 * hl) < 1e-9);
    assert_true(fabs(f.point[14].y - hl * (0.073 + 0.373 + 0.277 + 0.170 + 0.108)) < 1e-9);
    assert_true(fabs(f.point[14].x) < 1e-12 && fabs(f.point[14].z) < 1e-12);
    /* MCP flexed 90: the proximal phalanx points palmar (+Z); PIP flexed 90 more: the
       middle phalanx points back (-Y); DIP 90 more: the distal phalanx points dorsal */
    q[sk_hand_dof_find("M.MCP.flex")] = 90 * DEG;
    q[sk_hand_dof_find("M.PIP.flex")] = 90 * DEG;
    q[sk_hand_dof_find("M.DIP.flex")] = 90 * DEG;
    sk_hand_forward(&s, q, &f);
    sk_vec3d mcp = sk_v3d(0, hl * (0.073 + 0.373), 0);
    sk_vec3d pip = sk_v3d_add(mcp, sk_v3d(0, 0, 0.277 * hl));
    sk_vec3d dip = sk_v3d_add(pip, sk_v3d(0, -0.170 * hl, 0));
    sk_vec3d tip = sk_v3d_add(dip, sk_v3d(0, 0, -0.108 * hl));
    sk_vec3d want[4] = {mcp, pip, dip, tip};
    for (int k = 0; k < 4; k++)
        assert_true(sk_v3d_length(sk_v3d_sub(f.point[11 + k], want[k])) < 1e-9);
    /* wrist translation and a wrist flexion of 90 degrees: +Y maps to +Z */
    memset(q, 0, sizeof q);
    q[0] = 5;
    q[1] = -7;
    q[2] = 11;
    q[sk_hand_dof_find("wrist.flex")] = 90 * DEG;
    sk_hand_forward(&s, q, &f);
    double chain = hl * (0.073 + 0.373 + 0.277 + 0.170 + 0.108);
    assert_true(sk_v3d_length(sk_v3d_sub(f.point[14], sk_v3d(5, -7, 11 + chain))) < 1e-9);
    /* index abduction (radial, sign -1 on Z) moves the index tip toward +X */
    memset(q, 0, sizeof q);
    sk_hand_forward(&s, q, &f);
    double x0 = f.point[9].x;
    q[sk_hand_dof_find("I.MCP.abd")] = 10 * DEG;
    sk_hand_forward(&s, q, &f);
    assert_true(f.point[9].x > x0 + 5.0);
}

static void test_chain_is_product_of_joint_rotations(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double q[SK_HAND_DOF_COUNT];
    random_pose(&s, 3, q);
    sk_hand_frames f;
    sk_hand_forward(&s, q, &f);
    /* ring finger: R = E(wrist) M R1 R2 R3 R4 with R_j = mount Rz(sign abd) Rx(flex) (eq. 3.5) */
    int r0 = sk_hand_dof_find("R.CMC.flex");
    sk_mat3d acc = sk_hand_euler321(q[3], q[4], q[5]);
    sk_vec3d x = sk_v3d(q[0], q[1], q[2]);
    x = sk_v3d_add(x, sk_m3d_apply(acc, s.offset[12]));
    acc = sk_m3d_mul(acc, s.mount[12]);
    acc = sk_m3d_mul(acc, sk_m3d_mul(sk_m3d_rot_z(q[r0 + 1]), sk_m3d_rot_x(q[r0])));
    x = sk_v3d_add(x, sk_m3d_apply(acc, sk_v3d(0, s.length[12], 0)));
    acc = sk_m3d_mul(acc, sk_m3d_mul(sk_m3d_rot_z(q[r0 + 3]), sk_m3d_rot_x(q[r0 + 2])));
    x = sk_v3d_add(x, sk_m3d_apply(acc, sk_v3d(0, s.length[13], 0)));
    acc = sk_m3d_mul(acc, sk_m3d_rot_x(q[r0 + 4]));
    x = sk_v3d_add(x, sk_m3d_apply(acc, sk_v3d(0, s.length[14], 0)));
    acc = sk_m3d_mul(acc, sk_m3d_rot_x(q[r0 + 5]));
    x = sk_v3d_add(x, sk_m3d_apply(acc, sk_v3d(0, s.length[15], 0)));
    assert_true(sk_v3d_length(sk_v3d_sub(x, f.point[19])) < 1e-9);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) assert_true(fabs(acc.m[i][j] - f.rotation[15].m[i][j]) < 1e-12);
}

static void test_left_is_mirror_of_right(void **state)
{
    (void)state;
    sk_hand_skeleton r = make_skeleton(SK_HAND_SIDE_RIGHT), l = make_skeleton(SK_HAND_SIDE_LEFT);
    for (uint64_t seed = 0; seed < 20; seed++) {
        double q[SK_HAND_DOF_COUNT];
        random_pose(&r, seed, q);
        sk_hand_frames fr, fl;
        sk_hand_forward(&r, q, &fr);
        sk_hand_forward(&l, q, &fl);
        for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
            assert_true(fl.point[p].x == -fr.point[p].x);
            assert_true(fl.point[p].y == fr.point[p].y);
            assert_true(fl.point[p].z == fr.point[p].z);
        }
    }
    /* the thumb is on the +X side of the right hand, the -X side of the left */
    double zero[SK_HAND_DOF_COUNT] = {0};
    sk_hand_frames fr, fl;
    sk_hand_forward(&r, zero, &fr);
    sk_hand_forward(&l, zero, &fl);
    assert_true(fr.point[4].x > fr.point[24].x);
    assert_true(fl.point[4].x < fl.point[24].x);
}

static void test_anatomy_file_matches_builtin(void **state)
{
    (void)state;
    char path[512];
    snprintf(path, sizeof path, "%s/hand/anatomy.json", SK_TEST_PRESET_DIR);
    sk_hand_anatomy file, builtin;
    sk_error err = {0};
    sk_result r = sk_hand_anatomy_load_file(path, &file, &err);
    if (r != SK_OK) fprintf(stderr, "%s\n", err.message);
    assert_int_equal(r, SK_OK);
    sk_hand_anatomy_default(&builtin);
    assert_true(fabs(file.hand_length_mm - builtin.hand_length_mm) < 1e-12);
    assert_true(fabs(file.hand_breadth_mm - builtin.hand_breadth_mm) < 1e-12);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        assert_true(fabs(file.dof[i].min - builtin.dof[i].min) < 1e-12);
        assert_true(fabs(file.dof[i].max - builtin.dof[i].max) < 1e-12);
        assert_true(fabs(file.dof[i].relaxed - builtin.dof[i].relaxed) < 1e-12);
        assert_true(fabs(file.dof[i].stiffness - builtin.dof[i].stiffness) < 1e-12);
    }
    for (int f = 0; f < SK_HAND_FINGER_COUNT; f++) {
        const double *a = &file.finger[f].cmc_x_hb, *b = &builtin.finger[f].cmc_x_hb;
        for (int k = 0; k < (int)(sizeof(sk_hand_finger_data) / sizeof(double)); k++)
            assert_true(fabs(a[k] - b[k]) < 1e-12);
    }
    /* a bad value is named by its key path */
    const char *bad = "{\"dofs\": {\"I.PIP.flex\": {\"relaxed_deg\": 130}}}";
    assert_int_equal(sk_hand_anatomy_parse(bad, strlen(bad), "a.json", &file, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "dofs.I.PIP.flex.relaxed_deg"));
}

/* ------------------------------------------------------------ equilibrium */
/* (K + A'WA) theta - (tau - A'Wb), assembled here from the rows, independently of the
 * solver. */
static double residual_317(const sk_hand_skeleton *s, const sk_hand_constraints *c,
                           const double *torque, const double *dofs)
{
    double theta[SK_HAND_DOF_COUNT], res[SK_HAND_DOF_COUNT];
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        theta[i] = dofs[i] - s->dof[i].relaxed;
        double k = c && c->has_stiffness[i] ? c->stiffness[i] : s->dof[i].stiffness;
        res[i] = k * theta[i] - torque[i];
    }
    for (int r = 0; c && r < c->row_count; r++) {
        const sk_hand_row *row = &c->rows[r];
        double v = row->b;
        for (int a = 0; a < row->term_count; a++) v += row->coeff[a] * theta[row->dof[a]];
        for (int a = 0; a < row->term_count; a++)
            res[row->dof[a]] += row->coeff[a] * row->weight * v;
    }
    double m = 0.0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) m = fmax(m, fabs(res[i]));
    return m;
}

static void test_equilibrium_residual(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    const char *sets[2] = {"natural", "yasumuro-table-3.2"};
    for (int k = 0; k < 2; k++) {
        sk_hand_constraints *c = malloc(sizeof *c);
        load_constraints(sets[k], &s, c);
        sk_hand_solver *solver;
        sk_error err;
        assert_int_equal(sk_hand_solver_create(&solver, &s, c, NULL, 0, NULL, &err), SK_OK);
        sk_rng rng = sk_rng_make(11, (uint64_t)k, 0, 0);
        for (int t = 0; t < 20; t++) {
            sk_hand_input in = {0};
            /* small torques on flexion DOFs: inside the limits */
            for (int i = 6; i < SK_HAND_DOF_COUNT; i++)
                if (strstr(sk_hand_dof(i)->name, "flex") && !strstr(sk_hand_dof(i)->name, "CMC"))
                    in.torque[i] = sk_rng_range(&rng, 0.0, 0.15);
            double q[SK_HAND_DOF_COUNT];
            sk_hand_solve_info info;
            assert_int_equal(sk_hand_solve(solver, &in, q, &info, &err), SK_OK);
            if (info.clamped_count == 0) {
                assert_true(residual_317(&s, c, in.torque, q) < 1e-9);
                assert_true(info.residual < 1e-9);
            }
        }
        sk_hand_solver_destroy(solver);
        free(c);
    }
}

static void test_no_constraints_is_spring_law(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_solver *solver;
    sk_error err;
    assert_int_equal(sk_hand_solver_create(&solver, &s, NULL, NULL, 0, NULL, &err), SK_OK);
    sk_hand_input in = {0};
    sk_rng rng = sk_rng_make(5, 0, 0, 0);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) in.torque[i] = sk_rng_range(&rng, -0.02, 0.02);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_solve_info info;
    assert_int_equal(sk_hand_solve(solver, &in, q, &info, &err), SK_OK);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
        double want = s.dof[i].relaxed + in.torque[i] / s.dof[i].stiffness;
        if (want > s.dof[i].min && want < s.dof[i].max)
            assert_true(fabs(q[i] - want) < 1e-12);
        else
            assert_true(q[i] == s.dof[i].min || q[i] == s.dof[i].max);
    }
    sk_hand_solver_destroy(solver);
}

static void test_driving_one_dof_moves_coupled_dofs(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    /* y = 0.8 x (w = 2) and z = -0.5 y (w = 4): pinning x moves y by w a dx / (k + w) and z
       by the second row from y (one chain, solved exactly) */
    const char *json = "{\"rows\": ["
                       "{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 0.8, \"b\": 0, \"W\": 2},"
                       "{\"pair\": \"R.MCP.flex:M.MCP.abd\", \"A\": -0.5, \"b\": 0, \"W\": 4}]}";
    sk_hand_constraints *c = malloc(sizeof *c);
    sk_error err = {0};
    assert_int_equal(parse_constraints(json, &s, c, &err), SK_OK);
    sk_hand_solver *solver;
    assert_int_equal(sk_hand_solver_create(&solver, &s, c, NULL, 0, NULL, &err), SK_OK);
    int x = sk_hand_dof_find("L.MCP.flex"), y = sk_hand_dof_find("R.MCP.flex"),
        z = sk_hand_dof_find("M.MCP.abd");
    sk_hand_input in = {0};
    in.pinned[x] = true;
    double dx = 30 * DEG;
    in.pin_value[x] = s.dof[x].relaxed + dx;
    double q[SK_HAND_DOF_COUNT];
    assert_int_equal(sk_hand_solve(solver, &in, q, NULL, &err), SK_OK);
    /* solve the 2x2 system by hand: ky y + 2(y - 0.8 dx) + 4*(-0.5)(-0.5 y - z)... */
    double ky = s.dof[y].stiffness, kz = s.dof[z].stiffness;
    /* energy: ky/2 y^2 + kz/2 z^2 + 1 (0.8 dx - y)^2 + 2 (-0.5 y - z)^2 */
    double a11 = ky + 2.0 + 4.0 * 0.25, a12 = 4.0 * 0.5, a22 = kz + 4.0;
    double b1 = 2.0 * 0.8 * dx, b2 = 0.0;
    double det = a11 * a22 - a12 * a12;
    double yw = (b1 * a22 - a12 * b2) / det, zw = (a11 * b2 - a12 * b1) / det;
    assert_true(fabs((q[y] - s.dof[y].relaxed) - yw) < 1e-12);
    assert_true(fabs((q[z] - s.dof[z].relaxed) - zw) < 1e-12);
    /* directions: y follows x (positive slope), z opposes y (negative slope) */
    assert_true(q[y] - s.dof[y].relaxed > 0.0);
    assert_true(q[z] - s.dof[z].relaxed < 0.0);
    /* every other DOF stays relaxed */
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
        if (i != x && i != y && i != z) assert_true(q[i] == s.dof[i].relaxed);
    /* the natural set: driving the little MCP flexes the ring MCP more than the middle */
    load_constraints("natural", &s, c);
    sk_hand_solver_destroy(solver);
    assert_int_equal(sk_hand_solver_create(&solver, &s, c, NULL, 0, NULL, &err), SK_OK);
    assert_int_equal(sk_hand_solve(solver, &in, q, NULL, &err), SK_OK);
    double dr = q[y] - s.dof[y].relaxed, dm = q[sk_hand_dof_find("M.MCP.flex")] - s.dof[y].relaxed;
    assert_true(dr > dm && dm > 0.0);
    int lpip = sk_hand_dof_find("L.PIP.flex"), ldip = sk_hand_dof_find("L.DIP.flex");
    assert_true(q[ldip] - s.dof[ldip].relaxed > 0.0);
    assert_true(q[ldip] - s.dof[ldip].relaxed < q[lpip] - s.dof[lpip].relaxed);
    sk_hand_solver_destroy(solver);
    free(c);
}

/* The natural set's solver, for the fingertip reaches. */
static sk_hand_solver *natural_solver(const sk_hand_skeleton *s)
{
    sk_hand_constraints *c = malloc(sizeof *c);
    load_constraints("natural", s, c);
    sk_hand_solver *solver;
    sk_error err = {0};
    assert_int_equal(sk_hand_solver_create(&solver, s, c, NULL, 0, NULL, &err), SK_OK);
    free(c);
    return solver;
}

/* The tip of `finger` at the equilibrium of `in`. */
static sk_vec3d tip_of(const sk_hand_skeleton *s, sk_hand_solver *solver, const sk_hand_input *in,
                       sk_hand_finger finger, double q[SK_HAND_DOF_COUNT])
{
    sk_error err = {0};
    assert_int_equal(sk_hand_solve(solver, in, q, NULL, &err), SK_OK);
    sk_hand_frames fr;
    sk_hand_forward(s, q, &fr);
    return fr.point[sk_hand_fingertip_point(finger)];
}

static double distance(sk_vec3d a, sk_vec3d b)
{
    return sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/* A target the finger can reach (its tip at a pose of pinned reach DOFs) is reached
 * within the tolerance from the relaxed hand, with the coupling of the natural set; the
 * pose returned is the equilibrium of the inputs returned. */
static void test_reach_puts_the_fingertip_on_a_reachable_target(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_solver *solver = natural_solver(&s);
    assert_int_equal(sk_hand_fingertip_point(SK_HAND_THUMB), sk_hand_link_end_point(3));
    assert_string_equal(sk_hand_point_name(sk_hand_fingertip_point(SK_HAND_INDEX)), "I.tip");
    assert_string_equal(sk_hand_point_name(sk_hand_fingertip_point(SK_HAND_LITTLE)), "L.tip");
    const sk_hand_finger fingers[2] = {SK_HAND_INDEX, SK_HAND_THUMB};
    const double pose[2][3] = {{40 * DEG, 5 * DEG, 30 * DEG}, {20 * DEG, 10 * DEG, 15 * DEG}};
    for (int f = 0; f < 2; f++) {
        int dof[3];
        sk_hand_reach_dofs(fingers[f], dof);
        sk_hand_input aim = {0};
        for (int k = 0; k < 3; k++) {
            assert_true(dof[k] >= 0);
            aim.pinned[dof[k]] = true;
            aim.pin_value[dof[k]] = s.dof[dof[k]].relaxed + pose[f][k];
        }
        double q[SK_HAND_DOF_COUNT];
        sk_vec3d target = tip_of(&s, solver, &aim, fingers[f], q);
        sk_hand_input in = {0};
        double dofs[SK_HAND_DOF_COUNT], left = -1;
        sk_hand_relaxed(&s, dofs);
        sk_vec3d start = tip_of(&s, solver, &in, fingers[f], q);
        assert_true(distance(start, target) > 5.0); /* a real move */
        sk_hand_reach_desc d = {.finger = fingers[f], .target = target, .solver = solver};
        sk_hand_solve_info info;
        sk_error err = {0};
        assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, &info, &left, &err), SK_OK);
        assert_true(left >= 0.0 && left < 0.05);
        sk_hand_frames fr;
        sk_hand_forward(&s, dofs, &fr);
        assert_true(fabs(distance(fr.point[sk_hand_fingertip_point(fingers[f])], target) - left) <
                    1e-12);
        for (int k = 0; k < 3; k++) {
            assert_true(in.pinned[dof[k]]);
            assert_true(in.pin_value[dof[k]] >= s.dof[dof[k]].min &&
                        in.pin_value[dof[k]] <= s.dof[dof[k]].max);
        }
        assert_true(info.converged);
        tip_of(&s, solver, &in, fingers[f], q);
        assert_memory_equal(q, dofs, sizeof q);
    }
    sk_hand_solver_destroy(solver);
}

/* A target beyond the finger's reach ends at the nearest reach: no pose of the reach DOFs
 * on a grid over their limits puts the tip nearer (beyond a small margin), and the steps
 * never leave the tip farther than it started. */
static void test_reach_ends_nearest_an_unreachable_target(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_solver *solver = natural_solver(&s);
    int dof[3];
    sk_hand_reach_dofs(SK_HAND_INDEX, dof);
    sk_hand_input none = {0};
    double q[SK_HAND_DOF_COUNT];
    sk_vec3d start = tip_of(&s, solver, &none, SK_HAND_INDEX, q);
    /* 300 mm out from the palm: far beyond a finger */
    sk_vec3d target = {start.x + 40.0, start.y + 120.0, start.z + 270.0};
    sk_hand_input in = {0};
    double dofs[SK_HAND_DOF_COUNT], left;
    sk_hand_relaxed(&s, dofs);
    sk_hand_reach_desc d = {
        .finger = SK_HAND_INDEX, .target = target, .solver = solver, .max_iterations = 200};
    sk_error err = {0};
    assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, NULL, &left, &err), SK_OK);
    assert_true(left > 100.0);
    assert_true(left <= distance(start, target));
    double best = INFINITY;
    const int steps = 8;
    sk_hand_input grid = {0};
    for (int k = 0; k < 3; k++) grid.pinned[dof[k]] = true;
    for (int a = 0; a <= steps; a++)
        for (int b = 0; b <= steps; b++)
            for (int c = 0; c <= steps; c++) {
                const int at[3] = {a, b, c};
                for (int k = 0; k < 3; k++) {
                    const sk_hand_dof_data *dd = &s.dof[dof[k]];
                    grid.pin_value[dof[k]] = dd->min + (dd->max - dd->min) * at[k] / steps;
                }
                double g = distance(tip_of(&s, solver, &grid, SK_HAND_INDEX, q), target);
                if (g < best) best = g;
            }
    assert_true(left <= best + 0.5);
    sk_hand_solver_destroy(solver);
}

/* Bad reaches are refused and change nothing. */
static void test_reach_rejects_bad_targets(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_solver *solver = natural_solver(&s);
    sk_hand_input in = {0}, before;
    double dofs[SK_HAND_DOF_COUNT], kept[SK_HAND_DOF_COUNT], left = 7.0;
    sk_hand_relaxed(&s, dofs);
    memcpy(kept, dofs, sizeof kept);
    before = in;
    sk_error err = {0};
    sk_hand_reach_desc d = {.finger = SK_HAND_MIDDLE, .target = {NAN, 0, 0}, .solver = solver};
    assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, NULL, &left, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "target.x"));
    d.target = (sk_vec3d){0, INFINITY, 0};
    assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, NULL, &left, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    d.target = (sk_vec3d){0, 100, 0};
    d.finger = SK_HAND_FINGER_COUNT;
    assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, NULL, &left, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    d.finger = SK_HAND_MIDDLE;
    d.solver = NULL;
    assert_int_equal(sk_hand_reach(&s, &d, &in, dofs, NULL, &left, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_memory_equal(dofs, kept, sizeof kept);
    assert_memory_equal(&in, &before, sizeof in);
    assert_true(left == 7.0);
    int none[3];
    sk_hand_reach_dofs(SK_HAND_FINGER_COUNT, none);
    assert_true(none[0] == -1 && none[1] == -1 && none[2] == -1);
    assert_int_equal(sk_hand_fingertip_point(SK_HAND_FINGER_COUNT), -1);
    sk_hand_solver_destroy(solver);
}

static void test_limits_never_exceeded(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_constraints *c = malloc(sizeof *c);
    load_constraints("natural", &s, c);
    sk_hand_solver *solver;
    sk_error err;
    assert_int_equal(sk_hand_solver_create(&solver, &s, c, NULL, 0, NULL, &err), SK_OK);
    sk_rng rng = sk_rng_make(9, 0, 0, 0);
    int saw_clamped = 0;
    for (int t = 0; t < 200; t++) {
        sk_hand_input in = {0};
        for (int i = 6; i < SK_HAND_DOF_COUNT; i++) in.torque[i] = sk_rng_range(&rng, -4, 4);
        for (int p = 0; p < 3; p++) {
            int d = 6 + (int)sk_rng_below(&rng, SK_HAND_DOF_COUNT - 6);
            in.pinned[d] = true;
            in.pin_value[d] = sk_rng_range(&rng, -3, 3); /* often outside the limits */
        }
        double q[SK_HAND_DOF_COUNT];
        sk_hand_solve_info info;
        assert_int_equal(sk_hand_solve(solver, &in, q, &info, &err), SK_OK);
        assert_true(info.converged);
        saw_clamped += info.clamped_count > 0;
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
            assert_true(q[i] >= s.dof[i].min && q[i] <= s.dof[i].max);
        /* optimality (KKT): free DOFs balanced, DOFs at a limit pushed outward */
        double theta[SK_HAND_DOF_COUNT], g[SK_HAND_DOF_COUNT];
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++) theta[i] = q[i] - s.dof[i].relaxed;
        const double *h = sk_hand_solver_matrix(solver), *g0 = sk_hand_solver_rhs_constant(solver);
        for (int i = 0; i < SK_HAND_DOF_COUNT; i++) {
            g[i] = -(in.torque[i] + g0[i]);
            for (int j = 0; j < SK_HAND_DOF_COUNT; j++)
                g[i] += h[j * SK_HAND_DOF_COUNT + i] * theta[j];
            if (in.pinned[i]) continue;
            if (q[i] == s.dof[i].min)
                assert_true(g[i] > -1e-9);
            else if (q[i] == s.dof[i].max)
                assert_true(g[i] < 1e-9);
            else
                assert_true(fabs(g[i]) < 1e-9);
        }
    }
    assert_true(saw_clamped > 100);
    sk_hand_solver_destroy(solver);
    free(c);
}

/* ------------------------------------------------------ lookup tables */
static void curve_samples(double *xs, double *ys, int n)
{
    /* a curved region: PIP against MCP along a bent arc, as in Fig. 3.11 */
    for (int i = 0; i < n; i++) {
        double t = (double)i / (n - 1);
        xs[i] = (10 + 70 * t) * DEG;
        ys[i] = (15 + 80 * t * t) * DEG;
    }
}

static double fd_error(const sk_hand_lut *lut, double x, double y, double *gx_out)
{
    double gx, gy, e = 1e-7;
    sk_hand_lut_eval(lut, x, y, &gx, &gy);
    double fx = (sk_hand_lut_eval(lut, x + e, y, NULL, NULL) -
                 sk_hand_lut_eval(lut, x - e, y, NULL, NULL)) /
                (2 * e);
    double fy = (sk_hand_lut_eval(lut, x, y + e, NULL, NULL) -
                 sk_hand_lut_eval(lut, x, y - e, NULL, NULL)) /
                (2 * e);
    if (gx_out) *gx_out = gx;
    return fmax(fabs(gx - fx), fabs(gy - fy));
}

static void test_lut_gradients_match_finite_differences(void **state)
{
    (void)state;
    enum { N = 200 };
    double xs[N], ys[N];
    curve_samples(xs, ys, N);
    sk_error err;
    sk_hand_lut_desc d = {0};
    d.weight = 2.0;
    /* Hermite (default): the gradient is the exact derivative of the interpolated
       potential, inside and outside the grid */
    sk_hand_lut lut;
    assert_int_equal(sk_hand_lut_build(&lut, 31, 33, xs, ys, N, &d, &err), SK_OK);
    assert_int_equal(lut.n, 100);
    assert_int_equal(lut.interp, SK_HAND_LUT_INTERP_HERMITE);
    sk_rng rng = sk_rng_make(4, 0, 0, 0);
    for (int t = 0; t < 300; t++) {
        double x = sk_rng_range(&rng, lut.x0 - 0.3, lut.x0 + 99 * lut.h_x + 0.3);
        double y = sk_rng_range(&rng, lut.y0 - 0.3, lut.y0 + 99 * lut.h_y + 0.3);
        assert_true(fd_error(&lut, x, y, NULL) < 1e-5);
    }
    /* nodes hold the squared distance and its exact gradient 2 (p - nearest sample) */
    int i = 10, j = 20;
    double px = lut.x0 + i * lut.h_x, py = lut.y0 + j * lut.h_y, best = INFINITY, bx = 0;
    for (int k = 0; k < N; k++) {
        double q = (px - xs[k]) * (px - xs[k]) + (py - ys[k]) * (py - ys[k]);
        if (q < best) best = q, bx = px - xs[k];
    }
    double gx;
    assert_true(fabs(sk_hand_lut_eval(&lut, px, py, &gx, NULL) - d.weight * best) < 1e-12);
    assert_true(fabs(gx - d.weight * 2.0 * bx) < 1e-12);
    /* beyond the border the potential keeps growing as the squared distance: 1 rad left
       of the first sample it is about 1 */
    double far = sk_hand_lut_eval(&lut, xs[0] - 1.0, ys[0], NULL, NULL);
    assert_true(fabs(far - d.weight) < 0.01 * d.weight);
    sk_hand_lut_free(&lut);

    /* bilinear tables (the thesis's tables as they are) agree with the interpolated
       potential's slope to O(h): in cells whose corners share their nearest sample the
       mismatch is at most curvature (2) x h; across a Voronoi edge it grows by the
       spread of the corner gradients */
    d.interp = SK_HAND_LUT_INTERP_BILINEAR;
    assert_int_equal(sk_hand_lut_build(&lut, 31, 33, xs, ys, N, &d, &err), SK_OK);
    double h = fmax(lut.h_x, lut.h_y);
    int regular = 0;
    const int tries = 300;
    for (int t = 0; t < tries; t++) {
        double x = sk_rng_range(&rng, lut.x0 + 0.5 * lut.h_x, lut.x0 + 98.5 * lut.h_x);
        double y = sk_rng_range(&rng, lut.y0 + 0.5 * lut.h_y, lut.y0 + 98.5 * lut.h_y);
        int ci = (int)((x - lut.x0) / lut.h_x), cj = (int)((y - lut.y0) / lut.h_y);
        int at[4] = {cj * 100 + ci, cj * 100 + ci + 1, (cj + 1) * 100 + ci,
                     (cj + 1) * 100 + ci + 1};
        double spread = 0.0;
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++)
                spread = fmax(spread, fabs(lut.grad_x[at[a]] - lut.grad_x[at[b]]) +
                                          fabs(lut.grad_y[at[a]] - lut.grad_y[at[b]]));
        double e = fd_error(&lut, x, y, NULL);
        assert_true(e <= d.weight * (2.0 * h + spread) + 1e-6);
        regular += e <= 2.0 * h * d.weight;
    }
    assert_true(regular > tries * 8 / 10);
    sk_hand_lut_free(&lut);
}

static void test_lut_solve_converges_without_energy_increase(void **state)
{
    (void)state;
    enum { N = 200 };
    double xs[N], ys[N];
    curve_samples(xs, ys, N);
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_lut lut;
    sk_hand_lut_desc ld = {0};
    ld.weight = 3.0;
    sk_error err;
    int x = sk_hand_dof_find("I.MCP.flex"), y = sk_hand_dof_find("I.PIP.flex");
    assert_int_equal(sk_hand_lut_build(&lut, x, y, xs, ys, N, &ld, &err), SK_OK);
    sk_hand_constraints *c = malloc(sizeof *c);
    load_constraints("natural", &s, c);
    double previous = INFINITY, last_q = 0.0;
    for (int iters = 1; iters <= 40; iters++) {
        sk_hand_solver_desc sd = {0};
        sd.max_newton_iterations = iters;
        sk_hand_solver *solver;
        assert_int_equal(sk_hand_solver_create(&solver, &s, c, &lut, 1, &sd, &err), SK_OK);
        sk_hand_input in = {0};
        in.pinned[x] = true;
        in.pin_value[x] = 60 * DEG;
        double q[SK_HAND_DOF_COUNT];
        sk_hand_solve_info info;
        assert_int_equal(sk_hand_solve(solver, &in, q, &info, &err), SK_OK);
        /* each further iteration never raises the energy */
        assert_true(info.energy <= previous + 1e-12);
        previous = info.energy;
        last_q = q[y];
        if (iters == 40) {
            assert_true(info.converged);
            assert_true(info.residual <= 1e-6);
        }
        sk_hand_solver_destroy(solver);
    }
    /* the table pulls the PIP toward the measured curve: at MCP 60 the samples have
       PIP = 15 + 80 t^2 with t = 50/70, about 55.8 deg; the linear rows alone put it
       near the relaxed-line value */
    double t = 50.0 / 70.0, curve_pip = (15 + 80 * t * t) * DEG;
    sk_hand_solver *plain;
    assert_int_equal(sk_hand_solver_create(&plain, &s, c, NULL, 0, NULL, &err), SK_OK);
    sk_hand_input in = {0};
    in.pinned[x] = true;
    in.pin_value[x] = 60 * DEG;
    double q0[SK_HAND_DOF_COUNT];
    assert_int_equal(sk_hand_solve(plain, &in, q0, NULL, &err), SK_OK);
    assert_true(fabs(last_q - curve_pip) < fabs(q0[y] - curve_pip));
    sk_hand_solver_destroy(plain);
    sk_hand_lut_free(&lut);
    free(c);
}

/* ------------------------------------------------------------ calibration */
static void test_calibration_recovers_line_and_weight(void **state)
{
    (void)state;
    enum { N = 4000 };
    double *cols[SK_HAND_DOF_COUNT] = {0};
    static double a[N], b[N], c[N], d[N];
    sk_rng rng = sk_rng_make(21, 0, 0, 0);
    const double s1 = 0.02, s2 = 0.04;
    for (int i = 0; i < N; i++) {
        a[i] = sk_rng_range(&rng, 0.0, 1.4);
        b[i] = 0.7 * a[i] + 0.1 + s1 * sk_rng_normal(&rng);
        c[i] = sk_rng_range(&rng, 0.0, 1.2);
        d[i] = -0.3 * c[i] + 0.5 + s2 * sk_rng_normal(&rng);
    }
    cols[13] = a;
    cols[15] = b;
    cols[19] = c;
    cols[21] = d;
    int pairs[2][2] = {{13, 15}, {19, 21}};
    sk_hand_fit fits[2];
    sk_error err;
    assert_int_equal(sk_hand_calibrate((const double *const *)cols, N, (const int(*)[2])pairs, 2,
                                       SK_HAND_WEIGHT_THESIS, fits, &err),
                     SK_OK);
    assert_true(fabs(fits[0].slope - 0.7) < 0.01);
    assert_true(fabs(fits[0].intercept - 0.1) < 0.01);
    assert_true(fabs(fits[1].slope + 0.3) < 0.01);
    assert_true(fabs(fits[1].intercept - 0.5) < 0.01);
    /* noise on y only: the perpendicular spread is s^2 / (1 + a^2); eq. (3.18) scales by
       the largest */
    double m1 = s1 * s1 / (1 + 0.49), m2 = s2 * s2 / (1 + 0.09);
    assert_true(fabs(fits[0].mean_sq_distance / m1 - 1.0) < 0.08);
    assert_true(fabs(fits[1].weight - 1.0) < 1e-12);
    assert_true(fabs(fits[0].weight / (m1 / m2) - 1.0) < 0.1);
    assert_int_equal(sk_hand_calibrate((const double *const *)cols, N, (const int(*)[2])pairs, 2,
                                       SK_HAND_WEIGHT_INVERSE_VARIANCE, fits, &err),
                     SK_OK);
    assert_true(fabs(fits[0].weight - 1.0) < 1e-12);
    assert_true(fabs(fits[1].weight / (m1 / m2) - 1.0) < 0.1);
    /* the written file loads back as the same line (absolute angles, degrees) */
    const char *path = sk_test_path("hand/calib.json");
    assert_int_equal(
        sk_hand_fits_write_json(fits, 2, SK_HAND_WEIGHT_INVERSE_VARIANCE, "synthetic", path, &err),
        SK_OK);
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_constraints *cs = malloc(sizeof *cs);
    assert_int_equal(sk_hand_constraints_load_file(path, &s, cs, &err), SK_OK);
    assert_int_equal(cs->row_count, 2);
    /* row: a x - y + b = 0 on displacements: b = c + a xbar - ybar */
    double want_b = fits[0].intercept + fits[0].slope * s.dof[13].relaxed - s.dof[15].relaxed;
    assert_true(fabs(cs->rows[0].b - want_b) < 1e-9);
    assert_true(fabs(cs->rows[0].coeff[0] - fits[0].slope) < 1e-12);
    free(cs);
}

static void test_samples_csv_errors(void **state)
{
    (void)state;
    sk_hand_samples smp;
    sk_error err;
    const char *ok = "frame,I.MCP.flex,I.PIP.flex\n# comment\n0, 10, 20\n1,30,40\n";
    assert_int_equal(sk_hand_samples_parse(ok, strlen(ok), "s.csv", &smp, &err), SK_OK);
    assert_int_equal(smp.count, 2);
    assert_true(fabs(smp.column[15][1] - 40 * DEG) < 1e-15);
    sk_hand_samples_free(&smp);
    const char *bad_num = "I.MCP.flex,I.PIP.flex\n10,20\n30,4x0\n";
    assert_int_equal(sk_hand_samples_parse(bad_num, strlen(bad_num), "s.csv", &smp, &err),
                     SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "line 3, column 2 (I.PIP.flex)"));
    const char *bad_name = "I.MCP.flex,I.PIPflex\n10,20\n";
    assert_int_equal(sk_hand_samples_parse(bad_name, strlen(bad_name), "s.csv", &smp, &err),
                     SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "line 1, column 2: unknown DOF \"I.PIPflex\""));
    const char *short_line = "I.MCP.flex,I.PIP.flex\n10\n";
    assert_int_equal(sk_hand_samples_parse(short_line, strlen(short_line), "s.csv", &smp, &err),
                     SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "line 2: 1 fields, the header has 2"));
    int pairs[4][2], n;
    assert_int_equal(
        sk_hand_parse_pairs("R.MCP.flex:L.MCP.flex,I.PIP.flex:I.DIP.flex", pairs, 4, &n, &err),
        SK_OK);
    assert_int_equal(n, 2);
    assert_int_equal(pairs[1][1], 16);
    assert_int_equal(sk_hand_parse_pairs("R.MCP.flex:L.MCP.flx", pairs, 4, &n, &err),
                     SK_ERROR_INVALID_ARGUMENT);
}

/* ------------------------------------------------------ constraint files */
static void test_bad_constraint_files(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    sk_hand_constraints *c = malloc(sizeof *c);
    sk_error err;
    const char *unknown = "{\"rows\": [{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 1, \"W\": 1},"
                          "{\"pair\": \"L.MPC.flex:R.MCP.flex\", \"A\": 1, \"W\": 1}]}";
    assert_int_equal(parse_constraints(unknown, &s, c, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "test.json: rows[1].pair: unknown DOF \"L.MPC.flex\""));
    assert_int_equal(c->row_count, 0);
    const char *stiff = "{\"stiffness\": {\"I.MCP.flex\": -1}, \"rows\": []}";
    assert_int_equal(parse_constraints(stiff, &s, c, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "stiffness.I.MCP.flex = -1: stiffness must be positive"));
    const char *not_pd = "{\"rows\": [{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 1, \"W\": -5}]}";
    assert_int_equal(parse_constraints(not_pd, &s, c, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "not positive definite"));
    const char *mild_negative =
        "{\"rows\": [{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 1, \"W\": -0.2}]}";
    assert_int_equal(parse_constraints(mild_negative, &s, c, &err), SK_OK);
    const char *malformed = "{\"rows\": [\n{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 1,,}]}";
    assert_int_equal(parse_constraints(malformed, &s, c, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "test.json: line 2: malformed JSON"));
    const char *unknown_key =
        "{\"rows\": [{\"pair\": \"L.MCP.flex:R.MCP.flex\", \"A\": 1, \"W\": 1, \"w\": 2}]}";
    assert_int_equal(parse_constraints(unknown_key, &s, c, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "rows[0].w: unknown key"));
    const char *zero_w = "{\"rows\": [{\"terms\": {\"L.MCP.flex\": 1}, \"W\": 0}]}";
    assert_int_equal(parse_constraints(zero_w, &s, c, &err), SK_ERROR_INVALID_ARGUMENT);
    /* the shipped sets load, Table 3.2 with its six rows as printed */
    load_constraints("yasumuro-table-3.2", &s, c);
    assert_int_equal(c->row_count, 6);
    assert_true(fabs(c->rows[0].coeff[0] - 4.78) < 1e-15 && c->rows[0].coeff[1] == -1.0);
    assert_true(fabs(c->rows[0].b - (-2.01 * DEG)) < 1e-15);
    assert_true(fabs(c->rows[3].weight - 1.0) < 1e-15);
    load_constraints("natural", &s, c);
    assert_true(c->row_count >= 10);
    free(c);
}

/* ------------------------------------------------------------ keyframes */
static void test_keyframe_interpolation(void **state)
{
    (void)state;
    /* Bezier with flat handles: through the keys, at rest there, symmetric midpoint */
    assert_true(sk_hand_interpolate(SK_HAND_INTERP_BEZIER, 0, 1, 3, 9, 0.0) == 1.0);
    assert_true(sk_hand_interpolate(SK_HAND_INTERP_BEZIER, 0, 1, 3, 9, 1.0) == 3.0);
    assert_true(fabs(sk_hand_interpolate(SK_HAND_INTERP_BEZIER, 0, 1, 3, 9, 0.5) - 2.0) < 1e-15);
    double e = 1e-6;
    assert_true(fabs(sk_hand_interpolate(SK_HAND_INTERP_BEZIER, 0, 1, 3, 9, e) - 1.0) < 1e-10);
    /* Catmull-Rom: through the keys, slope (p2 - p0) / 2 at p1 */
    assert_true(fabs(sk_hand_interpolate(SK_HAND_INTERP_CATMULL_ROM, 0, 1, 3, 9, 1.0) - 3.0) <
                1e-15);
    double slope = (sk_hand_interpolate(SK_HAND_INTERP_CATMULL_ROM, 0, 1, 3, 9, e) - 1.0) / e;
    assert_true(fabs(slope - 1.5) < 1e-4);

    char path[512];
    snprintf(path, sizeof path, "%s/hand/little-mcp.json", SK_TEST_PRESET_DIR);
    sk_hand_animation *anim = malloc(sizeof *anim);
    sk_error err;
    assert_int_equal(sk_hand_animation_load_file(path, anim, &err), SK_OK);
    assert_int_equal(anim->key_count, 3);
    int frames = sk_hand_animation_frame_count(anim);
    assert_int_equal(frames, 2 * anim->steps + 1);
    int l = sk_hand_dof_find("L.MCP.flex");
    sk_hand_input in;
    sk_hand_animation_input(anim, anim->steps, &in);
    assert_true(in.pinned[l] && fabs(in.pin_value[l] - 85 * DEG) < 1e-12);
    sk_hand_animation_input(anim, anim->steps / 2, &in);
    assert_true(in.pin_value[l] > 34 * DEG && in.pin_value[l] < 85 * DEG);
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) assert_true(i == l || !in.pinned[i]);
    /* a channel set at keys 0 and 2 only passes through both and holds after */
    const char *json = "{\"steps\": 4, \"keys\": [{\"torque\": {\"I.PIP.flex\": 1}}, {},"
                       "{\"torque\": {\"I.PIP.flex\": 3}}, {}]}";
    assert_int_equal(sk_hand_animation_parse(json, strlen(json), "a.json", anim, &err), SK_OK);
    sk_hand_animation_input(anim, 4, &in);
    assert_true(fabs(in.torque[15] - 2.0) < 1e-12);
    sk_hand_animation_input(anim, 12, &in);
    assert_true(fabs(in.torque[15] - 3.0) < 1e-12);
    const char *bad = "{\"keys\": [{\"pin\": {\"L.MCP.flx\": 3}}]}";
    assert_int_equal(sk_hand_animation_parse(bad, strlen(bad), "a.json", anim, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "keys[0].pin.L.MCP.flx: unknown DOF"));
    free(anim);
}

/* ------------------------------------------------------------ export */
static void check_bvh_round_trip(sk_hand_side side)
{
    sk_hand_skeleton s = make_skeleton(side);
    enum { FRAMES = 12 };
    double q[FRAMES * SK_HAND_DOF_COUNT];
    for (int f = 0; f < FRAMES; f++) random_pose(&s, 100 + (uint64_t)f, q + f * SK_HAND_DOF_COUNT);
    const char *path = sk_test_path(side == SK_HAND_SIDE_LEFT ? "hand/left.bvh" : "hand/right.bvh");
    sk_error err;
    assert_int_equal(sk_hand_bvh_write(&s, q, FRAMES, 1.0 / 30.0, path, &err), SK_OK);
    sk_bvh *bvh = malloc(sizeof *bvh);
    sk_result r = sk_bvh_load_file(path, bvh, &err);
    if (r != SK_OK) fprintf(stderr, "%s\n", err.message);
    assert_int_equal(r, SK_OK);
    assert_int_equal(bvh->frame_count, FRAMES);
    assert_int_equal(bvh->channels_per_frame, 6 + 3 * (SK_HAND_LINK_COUNT - 1));
    assert_int_equal(bvh->joint_count, SK_HAND_LINK_COUNT + 5);
    int map[SK_HAND_POINT_COUNT];
    for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
        map[p] = sk_bvh_find(bvh, sk_hand_point_bvh_name(p));
        assert_true(map[p] >= 0);
    }
    sk_vec3d pos[SK_BVH_MAX_JOINTS];
    double worst = 0.0;
    for (int f = 0; f < FRAMES; f++) {
        sk_hand_frames fr;
        sk_hand_forward(&s, q + f * SK_HAND_DOF_COUNT, &fr);
        sk_bvh_positions(bvh, f, pos);
        for (int p = 0; p < SK_HAND_POINT_COUNT; p++)
            worst = fmax(worst, sk_v3d_length(sk_v3d_sub(pos[map[p]], fr.point[p])));
    }
    assert_true(worst < 1e-6);
    sk_bvh_free(bvh);
    free(bvh);
}

static void test_bvh_round_trip(void **state)
{
    (void)state;
    check_bvh_round_trip(SK_HAND_SIDE_RIGHT);
    check_bvh_round_trip(SK_HAND_SIDE_LEFT);
    sk_bvh bvh;
    sk_error err;
    const char *bad =
        "HIERARCHY\nROOT Hand\n{\n OFFSET 0 0 0\n CHANNELS 3 Xrotation Qrotation Z\n}\n";
    assert_int_equal(sk_bvh_parse(bad, strlen(bad), "b.bvh", &bvh, &err), SK_ERROR_PARSE);
    assert_non_null(strstr(err.message, "b.bvh: line 5: unknown channel \"Qrotation\""));
}

static void test_positions_export(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double q[2 * SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s, q);
    sk_hand_relaxed(&s, q + SK_HAND_DOF_COUNT);
    sk_error err;
    const char *csv = sk_test_path("hand/points.csv");
    assert_int_equal(sk_hand_positions_write(&s, q, 2, SK_HAND_POSITIONS_CSV, csv, &err), SK_OK);
    char *text;
    size_t size;
    assert_int_equal(sk_read_file(csv, 0, &text, &size, &err), SK_OK);
    assert_int_equal(sk_test_count_lines(text), 1 + 2 * SK_HAND_POINT_COUNT);
    assert_non_null(strstr(text, "1,L.tip,"));
    free(text);
    const char *json = sk_test_path("hand/points.json");
    assert_int_equal(sk_hand_positions_write(&s, q, 2, SK_HAND_POSITIONS_JSON, json, &err), SK_OK);
    assert_int_equal(sk_read_file(json, 0, &text, &size, &err), SK_OK);
    assert_non_null(strstr(text, "\"L.tip\""));
    free(text);
}

/* ------------------------------------------------------------ pictures */
/* The relaxed posture is the resting hand (Taylor & Schwarz 1955): finger flexion rises
 * from the index to the little finger at every joint, and the thumb rests beside the
 * index finger, on its palmar side. */
static void test_relaxed_posture_is_a_resting_hand(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    static const char *const joints[3] = {"MCP", "PIP", "DIP"};
    static const char fingers[4] = {'I', 'M', 'R', 'L'};
    for (int j = 0; j < 3; j++) {
        for (int f = 0; f + 1 < 4; f++) {
            char a[32], b[32];
            snprintf(a, sizeof a, "%c.%s.flex", fingers[f], joints[j]);
            snprintf(b, sizeof b, "%c.%s.flex", fingers[f + 1], joints[j]);
            assert_true(s.dof[sk_hand_dof_find(b)].relaxed > s.dof[sk_hand_dof_find(a)].relaxed);
        }
    }
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s, q);
    sk_hand_frames f;
    sk_hand_forward(&s, q, &f);
    /* distance from the thumb tip to the index's proximal phalanx (I.MCP - I.PIP) */
    sk_vec3d a = f.point[6], b = f.point[7], tip = f.point[4];
    sk_vec3d ab = sk_v3d_sub(b, a);
    double t = sk_clampd(sk_v3d_dot(sk_v3d_sub(tip, a), ab) / sk_v3d_dot(ab, ab), 0.0, 1.0);
    double dist = sk_v3d_length(sk_v3d_sub(tip, sk_v3d_add(a, sk_v3d_scale(ab, t))));
    assert_true(dist < 0.25 * s.hand_length_mm);
    assert_true(tip.z > f.point[6].z + 10.0); /* palmar of the index */
    assert_true(tip.x > f.point[11].x);       /* on the radial side of the middle finger */
}

static void flat_pose(double *q)
{
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) q[i] = 0.0;
}

/* The views are where the documentation says: dorsal shows a right hand's thumb on the
 * left, radial shows flexion curling to the left (palmar), and a left hand is the mirror
 * image; the layout keeps every point inside its panel. */
static void test_draw_view_conventions(void **state)
{
    (void)state;
    for (int side = SK_HAND_SIDE_RIGHT; side <= SK_HAND_SIDE_LEFT; side++) {
        sk_hand_skeleton s = make_skeleton((sk_hand_side)side);
        double q[SK_HAND_DOF_COUNT];
        sk_hand_relaxed(&s, q);
        q[sk_hand_dof_find("M.MCP.flex")] = 80 * DEG;
        sk_hand_draw_layout l;
        sk_error err = {0};
        assert_int_equal(sk_hand_draw_layout_fit(&s, q, 1, NULL, &l, &err), SK_OK);
        assert_int_equal(l.view_count, 2);
        assert_int_equal(l.panel[0].view, SK_HAND_VIEW_DORSAL);
        assert_int_equal(l.panel[1].view, SK_HAND_VIEW_RADIAL);
        sk_hand_frames f;
        sk_hand_forward(&s, q, &f);
        double mirror = side == SK_HAND_SIDE_RIGHT ? 1.0 : -1.0;
        sk_vec2d thumb = sk_hand_draw_project(&l, 0, f.point[4]),
                 little = sk_hand_draw_project(&l, 0, f.point[24]);
        assert_true(mirror * (little.x - thumb.x) > 50.0 * l.pixels_per_mm);
        /* radial view: the flexed middle fingertip lies palmar of its MCP, to the left for
           a right hand */
        sk_vec2d mcp = sk_hand_draw_project(&l, 1, f.point[11]),
                 tip = sk_hand_draw_project(&l, 1, f.point[14]);
        assert_true(mirror * (mcp.x - tip.x) > 40.0 * l.pixels_per_mm);
        /* fingers up: the middle MCP is above the wrist in both views */
        for (int v = 0; v < 2; v++)
            assert_true(sk_hand_draw_project(&l, v, f.point[11]).y <
                        sk_hand_draw_project(&l, v, f.point[0]).y);
        /* the projection is the documented formula, and every point is in its panel */
        for (int v = 0; v < 2; v++) {
            const sk_hand_panel *pn = &l.panel[v];
            for (int p = 0; p < SK_HAND_POINT_COUNT; p++) {
                sk_vec2d px = sk_hand_draw_project(&l, v, f.point[p]);
                double want_x = pn->origin_x + l.pixels_per_mm * sk_v3d_dot(f.point[p], pn->right);
                double want_y = pn->origin_y - l.pixels_per_mm * sk_v3d_dot(f.point[p], pn->up);
                assert_true(fabs(px.x - want_x) < 1e-9 && fabs(px.y - want_y) < 1e-9);
                assert_true(px.x > pn->x0 && px.x < pn->x0 + pn->width);
                assert_true(px.y > pn->y0 && px.y < pn->y0 + pn->height);
            }
        }
    }
}

/* Pixels land where the projection says: a bone's middle has its finger's colour, the
 * wrist disc is dark, a point beyond the fingertip is background. */
static void test_draw_pixels_at_projected_points(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double q[SK_HAND_DOF_COUNT];
    flat_pose(q);
    sk_hand_draw_desc d = {0};
    d.width = 800;
    d.height = 960;
    d.caption = "flat hand";
    sk_hand_draw_layout l;
    sk_error err = {0};
    assert_int_equal(sk_hand_draw_layout_fit(&s, q, 1, &d, &l, &err), SK_OK);
    sk_image img;
    assert_int_equal(sk_hand_draw(&s, q, &d, &l, &img, &err), SK_OK);
    assert_int_equal(img.width, 800);
    assert_int_equal(img.height, 960);
    assert_int_equal(img.channels, 3);
    sk_hand_frames f;
    sk_hand_forward(&s, q, &f);
    /* the flat hand lies in the wrist's plane: no depth fading in the dorsal view */
    for (int finger = SK_HAND_INDEX; finger <= SK_HAND_LITTLE; finger++) {
        int mcp = 5 * finger + 1, pip = mcp + 1;
        sk_vec3d mid = sk_v3d_scale(sk_v3d_add(f.point[mcp], f.point[pip]), 0.5);
        sk_vec2d px = sk_hand_draw_project(&l, 0, mid);
        const float *p = sk_image_pixel(&img, (int)px.x, (int)px.y);
        sk_color want = sk_hand_finger_color((sk_hand_finger)finger);
        assert_true(fabsf(p[0] - want.r) < 1e-3f && fabsf(p[1] - want.g) < 1e-3f &&
                    fabsf(p[2] - want.b) < 1e-3f);
    }
    sk_vec2d w = sk_hand_draw_project(&l, 0, f.point[0]);
    const float *wp = sk_image_pixel(&img, (int)(w.x + 0.6 * l.pixels_per_mm * 3.4), (int)w.y);
    assert_true(wp[0] < 0.3f && wp[1] < 0.3f);
    sk_vec2d beyond = sk_hand_draw_project(&l, 0, sk_v3d_add(f.point[14], sk_v3d(0, 8, 0)));
    const float *bp = sk_image_pixel(&img, (int)beyond.x, (int)beyond.y);
    assert_true(bp[0] == 1.0f && bp[1] == 1.0f && bp[2] == 1.0f);
    sk_image_free(&img);
    /* bad descs name the field */
    d.view_count = 5;
    assert_int_equal(sk_hand_draw(&s, q, &d, NULL, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "view_count"));
    d.view_count = 0;
    d.width = 32;
    assert_int_equal(sk_hand_draw(&s, q, &d, NULL, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "width"));
    d.width = 0;
    q[sk_hand_dof_find("M.DIP.flex")] = NAN;
    assert_int_equal(sk_hand_draw(&s, q, &d, NULL, &img, &err), SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "M.DIP.flex"));
}

/* Reach framing gives every pose of a hand the same scale and placement. */
static void test_draw_reach_framing_is_pose_independent(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double a[SK_HAND_DOF_COUNT], b[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s, a);
    sk_hand_relaxed(&s, b);
    b[sk_hand_dof_find("L.MCP.flex")] = 85 * DEG;
    b[sk_hand_dof_find("I.PIP.flex")] = 90 * DEG;
    sk_hand_draw_layout la, lb, lt;
    sk_error err = {0};
    assert_int_equal(sk_hand_draw_layout_fit(&s, a, 1, NULL, &la, &err), SK_OK);
    assert_int_equal(sk_hand_draw_layout_fit(&s, b, 1, NULL, &lb, &err), SK_OK);
    assert_true(la.pixels_per_mm == lb.pixels_per_mm);
    assert_true(la.panel[1].origin_x == lb.panel[1].origin_x &&
                la.panel[1].origin_y == lb.panel[1].origin_y);
    /* a tight framing of the relaxed pose shows it larger */
    sk_hand_draw_desc d = {0};
    d.framing = SK_HAND_FRAMING_TIGHT;
    assert_int_equal(sk_hand_draw_layout_fit(&s, a, 1, &d, &lt, &err), SK_OK);
    assert_true(lt.pixels_per_mm > la.pixels_per_mm);
}

/* Frames are the same bytes whatever the thread count, one file per frame. */
static void test_frames_write_png(void **state)
{
    (void)state;
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    enum { N = 5 };
    double q[N * SK_HAND_DOF_COUNT];
    for (int k = 0; k < N; k++) {
        sk_hand_relaxed(&s, q + k * SK_HAND_DOF_COUNT);
        q[k * SK_HAND_DOF_COUNT + sk_hand_dof_find("L.MCP.flex")] = (30 + 12 * k) * DEG;
    }
    sk_hand_draw_desc d = {0};
    d.width = 320;
    d.height = 200;
    const char *captions[N] = {"a", NULL, "c, with a longer caption that needs two lines", "d",
                               "e"};
    char dir1[512], dir2[512];
    snprintf(dir1, sizeof dir1, "%s", sk_test_path("hand/frames1"));
    snprintf(dir2, sizeof dir2, "%s", sk_test_path("hand/frames2"));
    sk_error err = {0};
    sk_threads_set(1);
    assert_int_equal(sk_hand_frames_write_png(&s, q, N, &d, captions, dir1, (sk_progress){0}, &err),
                     SK_OK);
    sk_threads_set(2);
    assert_int_equal(sk_hand_frames_write_png(&s, q, N, &d, captions, dir2, (sk_progress){0}, &err),
                     SK_OK);
    sk_threads_set(0);
    assert_int_equal(sk_test_count_files_containing(dir1, "frame_"), N);
    assert_int_equal(sk_test_count_files_containing(dir1, ".tmp"), 0);
    for (int k = 0; k < N; k++) {
        char p1[600], p2[600];
        snprintf(p1, sizeof p1, "%s/frame_%04d.png", dir1, k);
        snprintf(p2, sizeof p2, "%s/frame_%04d.png", dir2, k);
        char *t1, *t2;
        size_t n1, n2;
        assert_int_equal(sk_read_file(p1, 0, &t1, &n1, &err), SK_OK);
        assert_int_equal(sk_read_file(p2, 0, &t2, &n2, &err), SK_OK);
        assert_true(n1 == n2 && memcmp(t1, t2, n1) == 0);
        free(t1);
        free(t2);
    }
}

/* Angle plots list the driven DOFs first, then the most moving ones. */
static void test_angle_plot(void **state)
{
    (void)state;
    enum { N = 11 };
    double q[N * SK_HAND_DOF_COUNT] = {0};
    int l = sk_hand_dof_find("L.MCP.flex"), r = sk_hand_dof_find("R.MCP.flex");
    int p = sk_hand_dof_find("L.PIP.flex"), tx = sk_hand_dof_find("wrist.tx");
    for (int f = 0; f < N; f++) {
        q[f * SK_HAND_DOF_COUNT + l] = f * 5 * DEG;
        q[f * SK_HAND_DOF_COUNT + r] = f * 2 * DEG;
        q[f * SK_HAND_DOF_COUNT + p] = f * 3 * DEG;
        q[f * SK_HAND_DOF_COUNT + tx] = f * 100.0;      /* translations are not "moving joints" */
        q[f * SK_HAND_DOF_COUNT + 20] = f * 0.01 * DEG; /* below the threshold */
    }
    bool driven[SK_HAND_DOF_COUNT] = {false};
    driven[l] = true;
    int list[SK_HAND_DOF_COUNT];
    int n = sk_hand_moving_dofs(q, N, driven, 0.5 * DEG, list, 8);
    assert_int_equal(n, 3);
    assert_int_equal(list[0], l);
    assert_int_equal(list[1], p);
    assert_int_equal(list[2], r);
    assert_int_equal(sk_hand_moving_dofs(q, N, driven, 0.5 * DEG, list, 2), 2);
    sk_image img;
    sk_error err = {0};
    sk_plot_desc pd = {.width = 400, .height = 300};
    assert_int_equal(sk_hand_plot_angles(q, N, list, 3, driven, &pd, &img, &err), SK_OK);
    assert_int_equal(img.width, 400);
    assert_int_equal(img.height, 300);
    sk_image_free(&img);
    int bad[1] = {SK_HAND_DOF_COUNT};
    assert_int_equal(sk_hand_plot_angles(q, N, bad, 1, driven, NULL, &img, &err),
                     SK_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(err.message, "dof_list[0]"));
    /* the animation's driven DOFs: pinned, or a non-zero torque in some key */
    sk_hand_animation *anim = malloc(sizeof *anim);
    const char *json =
        "{\"keys\": [{\"pin\": {\"L.DIP.flex\": 10}, \"torque\": {\"I.PIP.flex\": 0}},"
        "{\"torque\": {\"M.MCP.flex\": 0.5}}]}";
    assert_int_equal(sk_hand_animation_parse(json, strlen(json), "a.json", anim, &err), SK_OK);
    sk_hand_animation_driven(anim, driven);
    int count = 0;
    for (int i = 0; i < SK_HAND_DOF_COUNT; i++) count += driven[i];
    assert_int_equal(count, 2);
    assert_true(driven[sk_hand_dof_find("L.DIP.flex")] && driven[sk_hand_dof_find("M.MCP.flex")]);
    free(anim);
}

/* The command line draws what the library draws; frames count the animation's frames;
 * a bad path fails with status 1 and leaves no file. */
static void test_cli_pictures(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    const char *png = sk_test_path("hand/cli-pose.png");
    assert_int_equal(sk_test_cli(run, "hand pose --caption '' --png '%s' -q", png), 0);
    sk_image img, lib;
    sk_error err = {0};
    assert_int_equal(sk_image_read_png(&img, png, NULL, NULL, NULL, &err), SK_OK);
    assert_int_equal(img.width, 800);
    assert_int_equal(img.height, 480);
    sk_hand_skeleton s = make_skeleton(SK_HAND_SIDE_RIGHT);
    double q[SK_HAND_DOF_COUNT];
    sk_hand_relaxed(&s, q);
    sk_hand_draw_layout l;
    assert_int_equal(sk_hand_draw_layout_fit(&s, q, 1, NULL, &l, &err), SK_OK);
    assert_int_equal(sk_hand_draw(&s, q, NULL, &l, &lib, &err), SK_OK);
    sk_hand_frames f;
    sk_hand_forward(&s, q, &f);
    for (int v = 0; v < 2; v++) {
        /* the middle of the ring finger's proximal phalanx: its colour, in the file too */
        sk_vec3d mid = sk_v3d_scale(sk_v3d_add(f.point[16], f.point[17]), 0.5);
        sk_vec2d px = sk_hand_draw_project(&l, v, mid);
        const float *a = sk_image_pixel(&img, (int)px.x, (int)px.y),
                    *b = sk_image_pixel(&lib, (int)px.x, (int)px.y);
        for (int c = 0; c < 3; c++) assert_true(fabsf(a[c] - b[c]) < 0.01f);
        /* nearer to the ring finger's colour than to any other finger's or the background */
        float best = INFINITY;
        int nearest = -1;
        for (int finger = -1; finger < SK_HAND_FINGER_COUNT; finger++) {
            sk_color c =
                finger < 0 ? sk_rgb(1, 1, 1) : sk_hand_finger_color((sk_hand_finger)finger);
            float d2 = (a[0] - c.r) * (a[0] - c.r) + (a[1] - c.g) * (a[1] - c.g) +
                       (a[2] - c.b) * (a[2] - c.b);
            if (d2 < best) best = d2, nearest = finger;
        }
        assert_int_equal(nearest, SK_HAND_RING);
    }
    sk_image_free(&img);
    sk_image_free(&lib);
    /* frames: one per animation frame */
    const char *dir = sk_test_path("hand/cli-frames");
    const char *plot = sk_test_path("hand/cli-plot.png");
    assert_int_equal(
        sk_test_cli(
            run,
            "hand animate '%s/hand/little-dip.json' -q --frames-dir '%s' --png-size 240x160 "
            "--views radial --plot '%s'",
            SK_TEST_PRESET_DIR, dir, plot),
        0);
    assert_int_equal(sk_test_count_files_containing(dir, "frame_"), 49);
    char first[600], last[600];
    snprintf(first, sizeof first, "%s/frame_0000.png", dir);
    snprintf(last, sizeof last, "%s/frame_0048.png", dir);
    assert_true(sk_test_file_exists(first) && sk_test_file_exists(last));
    assert_int_equal(sk_image_read_png(&img, last, NULL, NULL, NULL, &err), SK_OK);
    assert_int_equal(img.width, 240);
    assert_int_equal(img.height, 160);
    sk_image_free(&img);
    assert_int_equal(sk_image_read_png(&img, plot, NULL, NULL, NULL, &err), SK_OK);
    assert_int_equal(img.width, 800);
    assert_int_equal(img.height, 560);
    sk_image_free(&img);
    /* a bad --png path: status 1, one line, neither the picture nor the pose file */
    const char *json = sk_test_path("hand/cli-not-written.json");
    assert_int_equal(sk_test_cli(run, "hand pose --png '%s/no/such/folder/p.png' -o '%s'",
                                 SK_TEST_TMP_DIR, json),
                     1);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_false(sk_test_file_exists(json));
    /* bad picture options: status 2 */
    assert_int_equal(sk_test_cli(run, "hand pose --png '%s' --views dorsal,sideways", png), 2);
    assert_non_null(strstr(run->err, "--views"));
    assert_int_equal(sk_test_cli(run, "hand pose --png '%s' --png-size 40x40", png), 2);
    assert_int_equal(
        sk_test_cli(run, "hand animate '%s/hand/little-dip.json' --plot '%s' --plot-dofs L.DIP.flx",
                    SK_TEST_PRESET_DIR, plot),
        2);
    assert_non_null(strstr(run->err, "L.DIP.flx"));
    assert_int_equal(sk_test_cli(run, "hand pose --labels"), 2);
    assert_non_null(strstr(run->err, "--labels needs --png"));
    free(run);
}

/* ------------------------------------------------------------ command line */
static void test_cli(void **state)
{
    (void)state;
    sk_test_run *run = malloc(sizeof *run);
    const char *pose = sk_test_path("hand/cli-pose.json");
    assert_int_equal(sk_test_cli(run, "hand pose --pin L.MCP.flex=60 -o '%s'", pose), 0);
    char *text;
    size_t size;
    sk_error err;
    assert_int_equal(sk_read_file(pose, 0, &text, &size, &err), SK_OK);
    assert_non_null(strstr(text, "\"L.MCP.flex\":\t60"));
    free(text);
    /* bad input: one line, exit 2, no output file */
    const char *none = sk_test_path("hand/cli-none.json");
    assert_int_equal(sk_test_cli(run, "hand pose --pin L.MPC.flex=60 -o '%s'", none), 2);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_non_null(strstr(run->err, "unknown DOF \"L.MPC.flex\""));
    assert_false(sk_test_file_exists(none));
    assert_int_equal(sk_test_cli(run, "hand pose --torque I.PIP.flex=abc"), 2);
    assert_int_equal(sk_test_cli(run, "hand pose --constraints nosuchset"), 2);
    /* calibrate: a CSV with a bad field names its line and column */
    const char *csv = sk_test_path("hand/cli-bad.csv");
    const char *bad = "R.MCP.flex,L.MCP.flex\n10,12\n20,2x\n";
    sk_test_write_file(csv, bad, strlen(bad));
    assert_int_equal(
        sk_test_cli(run, "hand calibrate '%s' --pairs R.MCP.flex:L.MCP.flex -o '%s'", csv, none),
        2);
    assert_int_equal(sk_test_count_lines(run->err), 1);
    assert_non_null(strstr(run->err, "line 3, column 2 (L.MCP.flex)"));
    const char *good = "R.MCP.flex,L.MCP.flex\n10,12\n20,25\n30,35\n40,49\n";
    sk_test_write_file(csv, good, strlen(good));
    const char *rows = sk_test_path("hand/cli-rows.json");
    assert_int_equal(
        sk_test_cli(run, "hand calibrate '%s' --pairs R.MCP.flex:L.MCP.flex -o '%s'", csv, rows),
        0);
    /* the fitted rows drive a pose */
    assert_int_equal(sk_test_cli(run, "hand pose --constraints '%s' --pin R.MCP.flex=50", rows), 0);
    assert_non_null(strstr(run->out, "L.MCP.flex"));
    /* lookup-table potentials from the same samples */
    assert_int_equal(
        sk_test_cli(
            run, "hand pose --samples '%s' --pairs R.MCP.flex:L.MCP.flex --pin R.MCP.flex=30", csv),
        0);
    /* animate the shipped demonstration into BVH and positions */
    const char *bvh = sk_test_path("hand/cli-little.bvh");
    const char *pos = sk_test_path("hand/cli-little.csv");
    assert_int_equal(
        sk_test_cli(run, "hand animate '%s/hand/little-mcp.json' --bvh '%s' --positions '%s' -q",
                    SK_TEST_PRESET_DIR, bvh, pos),
        0);
    sk_bvh *b = malloc(sizeof *b);
    assert_int_equal(sk_bvh_load_file(bvh, b, &err), SK_OK);
    assert_int_equal(b->frame_count, 49);
    sk_bvh_free(b);
    free(b);
    assert_int_equal(sk_test_cli(run, "hand animate '%s/hand/little-mcp.json'", SK_TEST_PRESET_DIR),
                     2);
    assert_int_equal(sk_test_cli(run, "hand pose --help"), 0);
    assert_non_null(strstr(run->out, "--pin"));
    free(run);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dof_table),
        cmocka_unit_test(test_euler_is_product_of_axis_rotations),
        cmocka_unit_test(test_forward_kinematics_hand_computed),
        cmocka_unit_test(test_chain_is_product_of_joint_rotations),
        cmocka_unit_test(test_left_is_mirror_of_right),
        cmocka_unit_test(test_anatomy_file_matches_builtin),
        cmocka_unit_test(test_equilibrium_residual),
        cmocka_unit_test(test_no_constraints_is_spring_law),
        cmocka_unit_test(test_driving_one_dof_moves_coupled_dofs),
        cmocka_unit_test(test_limits_never_exceeded),
        cmocka_unit_test(test_reach_puts_the_fingertip_on_a_reachable_target),
        cmocka_unit_test(test_reach_ends_nearest_an_unreachable_target),
        cmocka_unit_test(test_reach_rejects_bad_targets),
        cmocka_unit_test(test_lut_gradients_match_finite_differences),
        cmocka_unit_test(test_lut_solve_converges_without_energy_increase),
        cmocka_unit_test(test_calibration_recovers_line_and_weight),
        cmocka_unit_test(test_samples_csv_errors),
        cmocka_unit_test(test_bad_constraint_files),
        cmocka_unit_test(test_keyframe_interpolation),
        cmocka_unit_test(test_bvh_round_trip),
        cmocka_unit_test(test_positions_export),
        cmocka_unit_test(test_cli),
        cmocka_unit_test(test_relaxed_posture_is_a_resting_hand),
        cmocka_unit_test(test_draw_view_conventions),
        cmocka_unit_test(test_draw_pixels_at_projected_points),
        cmocka_unit_test(test_draw_reach_framing_is_pose_independent),
        cmocka_unit_test(test_frames_write_png),
        cmocka_unit_test(test_angle_plot),
        cmocka_unit_test(test_cli_pictures),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
