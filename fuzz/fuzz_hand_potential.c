/* Fuzz harness: the calibrated-potential JSON reader (sk_hand_potential_parse); a file
 * that reads must give a solver whose solve keeps every DOF within its limits. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "shitsukan/hand.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    sk_hand_skeleton skel;
    if (sk_hand_skeleton_init(&skel, NULL, NULL) != SK_OK) abort();
    sk_hand_potential p;
    if (sk_hand_potential_parse((const char *)data, size, "fuzz", &skel, &p, NULL) != SK_OK) {
        if (p.component) abort();
        return 0;
    }
    sk_hand_potential_solver *ps = NULL;
    if (sk_hand_potential_solver_create(&ps, &skel, &p, NULL, NULL) == SK_OK) {
        sk_hand_input in = {0};
        int pin = p.dof[0];
        in.pinned[pin] = true;
        in.pin_value[pin] = 0.5 * (skel.dof[pin].min + skel.dof[pin].max);
        double q[SK_HAND_DOF_COUNT];
        if (sk_hand_potential_solve(ps, &in, q, NULL, NULL, NULL) == SK_OK)
            for (int i = 0; i < SK_HAND_DOF_COUNT; i++)
                if (!(q[i] >= skel.dof[i].min && q[i] <= skel.dof[i].max)) abort();
        sk_hand_potential_solver_destroy(ps);
    }
    sk_hand_potential_free(&p);
    return 0;
}
