/* Old names of the render module kept for one release (docs/architecture.md lists them
 * with their new names). */
#include "shitsukan/render.h"

sk_result sk_render_compute_tangents(sk_mesh *mesh, sk_error *err)
{
    return sk_mesh_compute_tangents(mesh, err);
}
