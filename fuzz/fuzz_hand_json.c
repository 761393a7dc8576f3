/* Fuzz harness: the hand's strict JSON helpers (src/formats/hand/hand_json.c) that every hand
 * reader goes through: the parse, key checks, ranged numbers, strings, DOF names and
 * finger letters, on whatever object the input holds. */
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include "models/hand/hand_internal.h"
#include "formats/hand/hand_json_internal.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    cJSON *root = NULL;
    if (sk__hand_json_parse((const char *)data, size, "fuzz", &root, NULL) != SK_OK) return 0;
    static const char *const keys[] = {"dofs", "keys", "rows", "name", NULL};
    if (sk__hand_json_expect_object(root, "", NULL) == SK_OK) {
        sk__hand_json_check_keys(root, "", keys, NULL);
        for (const cJSON *item = root->child; item; item = item->next) {
            double v = 0.0;
            const char *text = NULL;
            sk__hand_json_number(root, "", item->string, -180.0, 180.0, true, &v, NULL);
            if (sk__hand_json_string(root, "", item->string, &text, NULL) == SK_OK && text) {
                int dof = -1;
                sk__hand_dof_by_name(text, item->string, &dof, NULL);
                sk__hand_finger_by_letter(text);
            }
            if (cJSON_IsObject(item)) sk__hand_json_check_keys(item, item->string, keys, NULL);
        }
    }
    cJSON_Delete(root);
    return 0;
}
