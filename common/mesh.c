/* mesh.c: see mesh.h. */
#include "mesh.h"

#include <string.h>

bool mesh_face_in(const Mesh *m, int face, const char *name)
{
    if (face < 0 || face >= m->nfaces || m->faces[face].names < 0)
        return false;
    const NameSet *set = &m->sets[m->faces[face].names];
    if (set->object && strcmp(set->object, name) == 0)
        return true;
    for (int k = 0; k < set->ngroups; k++)
        if (strcmp(set->groups[k], name) == 0)
            return true;
    return false;
}
