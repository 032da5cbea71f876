/* mesh.c: building a mesh, one vertex, material and face at a time.
 *
 * Reading and writing OBJ files is in obj.c, ear clipping in triangulate.c.
 * Every array grows by doubling; every count is checked against the limits of
 * mesh.h before anything is allocated, so a hostile file meets an error, not an
 * overflow. */
#include "mesh.h"

#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Corner positions of a face are gathered on the stack up to this many. */
#define SMALL_FACE 32
#define FIRST_CAPACITY 16

void mesh_init(Mesh *m)
{
    memset(m, 0, sizeof *m);
}

void mesh_free(Mesh *m)
{
    free(m->verts);
    free(m->corners);
    free(m->faces);
    free(m->tris);
    free(m->materials);
    for (int i = 0; i < m->nwarnings; i++)
        free(m->warnings[i]);
    free(m->warnings);
    for (int i = 0; i < m->nlibraries; i++)
        free(m->libraries[i]);
    free(m->libraries);
    mesh_init(m);
}

/* Makes room for `need` items in *items (capacity *cap, items of `size` bytes). */
static bool reserve(void **items, int *cap, int need, size_t size, Error *err)
{
    if (need <= *cap)
        return true;
    long long new_cap = *cap > 0 ? *cap : FIRST_CAPACITY;
    while (new_cap < need)
        new_cap *= 2;
    if (new_cap > INT_MAX)
        new_cap = INT_MAX;
    if ((unsigned long long)new_cap > SIZE_MAX / size)
        return error_set(err, "out of memory");
    void *grown = realloc(*items, (size_t)new_cap * size);
    if (!grown)
        return error_set(err, "out of memory");
    *items = grown;
    *cap = (int)new_cap;
    return true;
}

int mesh_add_vertex(Mesh *m, Vec3 p, Error *err)
{
    if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z)) {
        error_set(err, "vertex (%g, %g, %g) is not made of finite numbers", p.x, p.y, p.z);
        return -1;
    }
    if (m->nverts >= MESH_MAX_VERTICES) {
        error_set(err, "too many vertices (at most %d)", MESH_MAX_VERTICES);
        return -1;
    }
    if (!reserve((void **)&m->verts, &m->cap_verts, m->nverts + 1, sizeof *m->verts, err))
        return -1;
    m->verts[m->nverts] = p;
    return m->nverts++;
}

/* A name that an OBJ/MTL file can carry back: one line, no comment sign, no
 * white space at either end (mtl and usemtl names are read as the rest of the
 * line, trimmed). */
static bool material_name_ok(const char *name, Error *err)
{
    size_t len = strlen(name);
    if (len == 0)
        return error_set(err, "a material needs a name");
    if (len >= MATERIAL_NAME_MAX)
        return error_set(err, "material name '%.*s...' is too long (at most %d bytes)",
                         MATERIAL_NAME_MAX / 2, name, MATERIAL_NAME_MAX - 1);
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)name[i];
        if (c == '#' || c == '\n' || c == '\r')
            return error_set(err, "material name '%s' has a character an MTL file cannot hold",
                             name);
    }
    const char *blank = " \t\v\f";
    if (strchr(blank, name[0]) || strchr(blank, name[len - 1]))
        return error_set(err, "material name '%s' starts or ends with white space", name);
    return true;
}

static double clamp01(double x)
{
    return x < 0 ? 0 : x > 1 ? 1 : x;
}

int mesh_add_material(Mesh *m, const char *name, Vec3 kd, Error *err)
{
    if (!material_name_ok(name, err))
        return -1;
    if (!isfinite(kd.x) || !isfinite(kd.y) || !isfinite(kd.z)) {
        error_set(err, "material '%s': colour is not made of finite numbers", name);
        return -1;
    }
    if (m->nmaterials >= MESH_MAX_MATERIALS) {
        error_set(err, "too many materials (at most %d)", MESH_MAX_MATERIALS);
        return -1;
    }
    if (!reserve((void **)&m->materials, &m->cap_materials, m->nmaterials + 1,
                 sizeof *m->materials, err))
        return -1;
    Material *mat = &m->materials[m->nmaterials];
    memset(mat, 0, sizeof *mat);
    strcpy(mat->name, name);
    mat->kd = vec3(clamp01(kd.x), clamp01(kd.y), clamp01(kd.z));
    mat->has_kd = true;
    return m->nmaterials++;
}

static bool face_ok(const Mesh *m, const int *vertex_indices, int n, int material, Error *err)
{
    if (n < 3)
        return error_set(err, "a face needs at least 3 corners, not %d", n);
    if (n > MESH_MAX_FACE_VERTICES)
        return error_set(err, "a face has at most %d corners, not %d", MESH_MAX_FACE_VERTICES, n);
    if (material < -1 || material >= m->nmaterials)
        return error_set(err, "material %d does not exist (there are %d)", material,
                         m->nmaterials);
    for (int i = 0; i < n; i++)
        if (vertex_indices[i] < 0 || vertex_indices[i] >= m->nverts)
            return error_set(err, "face corner %d uses vertex %d, but the vertices are 0 to %d",
                             i, vertex_indices[i], m->nverts - 1);
    if (m->ncorners > MESH_MAX_CORNERS - n)
        return error_set(err, "too many face corners (at most %d)", MESH_MAX_CORNERS);
    return true;
}

int mesh_add_face(Mesh *m, const int *vertex_indices, int n, int material, Error *err)
{
    if (!face_ok(m, vertex_indices, n, material, err))
        return -1;
    /* A face of n corners has n - 2 triangles, so tris never outgrow corners. */
    if (!reserve((void **)&m->corners, &m->cap_corners, m->ncorners + n, sizeof *m->corners, err) ||
        !reserve((void **)&m->tris, &m->cap_tris, m->ntris + n - 2, sizeof *m->tris, err) ||
        !reserve((void **)&m->faces, &m->cap_faces, m->nfaces + 1, sizeof *m->faces, err))
        return -1;

    Vec3 small[SMALL_FACE];
    Vec3 *pts = n <= SMALL_FACE ? small : malloc(sizeof *pts * (size_t)n);
    if (!pts) {
        error_set(err, "out of memory");
        return -1;
    }
    for (int i = 0; i < n; i++)
        pts[i] = m->verts[vertex_indices[i]];

    Face *f = &m->faces[m->nfaces];
    f->first = m->ncorners;
    f->count = n;
    f->material = material;
    f->first_tri = m->ntris;
    memcpy(m->corners + m->ncorners, vertex_indices, sizeof *vertex_indices * (size_t)n);
    m->ncorners += n;
    m->ntris += triangulate_polygon(pts, n, m->tris + m->ntris, &f->convex);
    if (pts != small)
        free(pts);
    return m->nfaces++;
}
