/* Node transforms of glTF 2.0 (sec. 3.5.3): local matrix = T * R * S, world matrix = the
 * parent's world matrix times the local one; column-major 4x4 matrices in double. Used for
 * the inverse bind matrices of skins and to read nodes given as a matrix. */
#include <math.h>
#include <string.h>

#include "formats/gltf_internal.h"

#define M(m, row, col) (m)[(col)*4 + (row)]

void sk__gltf_trs_matrix(const double t[3], const double r[4], const double s[3], double out[16])
{
    double x = r[0], y = r[1], z = r[2], w = r[3];
    /* rotation matrix of a unit quaternion */
    double rot[3][3] = {
        {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
        {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
        {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)},
    };
    memset(out, 0, 16 * sizeof(double));
    for (int row = 0; row < 3; row++) {
        for (int col = 0; col < 3; col++) M(out, row, col) = rot[row][col] * s[col];
        M(out, row, 3) = t[row];
    }
    M(out, 3, 3) = 1.0;
}

void sk__gltf_matrix_mul(const double a[16], const double b[16], double out[16])
{
    double tmp[16];
    for (int row = 0; row < 4; row++)
        for (int col = 0; col < 4; col++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++) sum += M(a, row, k) * M(b, k, col);
            M(tmp, row, col) = sum;
        }
    memcpy(out, tmp, sizeof tmp);
}

bool sk__gltf_affine_inverse(const double m[16], double out[16])
{
    double a = M(m, 0, 0), b = M(m, 0, 1), c = M(m, 0, 2);
    double d = M(m, 1, 0), e = M(m, 1, 1), f = M(m, 1, 2);
    double g = M(m, 2, 0), h = M(m, 2, 1), k = M(m, 2, 2);
    double co00 = e * k - f * h, co01 = f * g - d * k, co02 = d * h - e * g;
    double det = a * co00 + b * co01 + c * co02;
    if (!(fabs(det) > 0.0) || !isfinite(det)) return false;
    double inv[3][3] = {
        {co00 / det, (c * h - b * k) / det, (b * f - c * e) / det},
        {co01 / det, (a * k - c * g) / det, (c * d - a * f) / det},
        {co02 / det, (b * g - a * h) / det, (a * e - b * d) / det},
    };
    double tmp[16] = {0};
    for (int row = 0; row < 3; row++) {
        double tr = 0.0;
        for (int col = 0; col < 3; col++) {
            M(tmp, row, col) = inv[row][col];
            tr -= inv[row][col] * M(m, col, 3);
        }
        M(tmp, row, 3) = tr;
    }
    M(tmp, 3, 3) = 1.0;
    memcpy(out, tmp, sizeof tmp);
    return true;
}

void sk__gltf_node_world(const sk_gltf *gltf, int node, double out[16])
{
    const sk__gltf_node *n = &gltf->nodes[node];
    sk__gltf_trs_matrix(n->translation, n->rotation, n->scale, out);
    /* parents are earlier nodes, so the walk up always ends */
    for (int p = n->parent; p != SK_GLTF_NONE; p = gltf->nodes[p].parent) {
        const sk__gltf_node *pn = &gltf->nodes[p];
        double local[16];
        sk__gltf_trs_matrix(pn->translation, pn->rotation, pn->scale, local);
        sk__gltf_matrix_mul(local, out, out);
    }
}

bool sk__gltf_matrix_to_trs(const double m[16], double t[3], double r[4], double s[3])
{
    if (M(m, 3, 0) != 0.0 || M(m, 3, 1) != 0.0 || M(m, 3, 2) != 0.0 || M(m, 3, 3) != 1.0)
        return false;
    double col[3][3];
    for (int c = 0; c < 3; c++) {
        for (int row = 0; row < 3; row++) col[c][row] = M(m, row, c);
        s[c] = sqrt(col[c][0] * col[c][0] + col[c][1] * col[c][1] + col[c][2] * col[c][2]);
        if (!(s[c] > 0.0) || !isfinite(s[c])) return false;
        for (int row = 0; row < 3; row++) col[c][row] /= s[c];
        t[c] = M(m, c, 3);
    }
    double det = col[0][0] * (col[1][1] * col[2][2] - col[2][1] * col[1][2]) -
                 col[1][0] * (col[0][1] * col[2][2] - col[2][1] * col[0][2]) +
                 col[2][0] * (col[0][1] * col[1][2] - col[1][1] * col[0][2]);
    if (det < 0) {
        s[0] = -s[0];
        for (int row = 0; row < 3; row++) col[0][row] = -col[0][row];
    }
    /* orthonormal columns or it has a shear (tolerance for float-stored matrices) */
    for (int a = 0; a < 3; a++)
        for (int b = a + 1; b < 3; b++) {
            double dot = col[a][0] * col[b][0] + col[a][1] * col[b][1] + col[a][2] * col[b][2];
            if (fabs(dot) > 1e-4) return false;
        }
    /* rotation matrix R[row][c] = col[c][row] to a quaternion (Shepperd's method) */
    double r00 = col[0][0], r11 = col[1][1], r22 = col[2][2];
    double trace = r00 + r11 + r22, x, y, z, w;
    if (trace > 0) {
        double q = 2.0 * sqrt(1.0 + trace);
        w = 0.25 * q;
        x = (col[1][2] - col[2][1]) / q;
        y = (col[2][0] - col[0][2]) / q;
        z = (col[0][1] - col[1][0]) / q;
    } else if (r00 > r11 && r00 > r22) {
        double q = 2.0 * sqrt(1.0 + r00 - r11 - r22);
        w = (col[1][2] - col[2][1]) / q;
        x = 0.25 * q;
        y = (col[1][0] + col[0][1]) / q;
        z = (col[2][0] + col[0][2]) / q;
    } else if (r11 > r22) {
        double q = 2.0 * sqrt(1.0 + r11 - r00 - r22);
        w = (col[2][0] - col[0][2]) / q;
        x = (col[1][0] + col[0][1]) / q;
        y = 0.25 * q;
        z = (col[2][1] + col[1][2]) / q;
    } else {
        double q = 2.0 * sqrt(1.0 + r22 - r00 - r11);
        w = (col[0][1] - col[1][0]) / q;
        x = (col[2][0] + col[0][2]) / q;
        y = (col[2][1] + col[1][2]) / q;
        z = 0.25 * q;
    }
    double len = sqrt(x * x + y * y + z * z + w * w);
    r[0] = x / len, r[1] = y / len, r[2] = z / len, r[3] = w / len;
    return true;
}
