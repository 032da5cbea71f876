/* mesh_build.c: building a mesh, one vertex, material and face at a time.
 *
 * Reading and writing OBJ files is in obj.c, ear clipping in triangulate.c.
 * Every array grows by doubling; every count is checked against the limits of
 * mesh_build.h before anything is allocated, so a hostile file meets an error, not an
 * overflow. */
#include "mesh_build.h"

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

static void free_set(Mesh *m, NameSet *set);

void mesh_free(Mesh *m)
{
    free(m->verts);
    free(m->corners);
    free(m->faces);
    free(m->tris);
    free(m->materials);
    for (int i = 0; i < m->nsets; i++)
        free_set(m, &m->sets[i]);
    free(m->sets);
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

/* A name that an OBJ/MTL file can carry back: one line, no comment sign, of
 * 1 to max - 1 bytes; no white space at either end (mtl, usemtl and o names
 * are read as the rest of the line, trimmed), or none at all for one word (a
 * g name). what says which kind of name, for the message. */
static bool name_ok(const char *what, const char *name, size_t max, bool one_word, Error *err)
{
    size_t len = strlen(name);
    if (len == 0)
        return error_set(err, "a %s needs a name", what);
    if (len >= max)
        return error_set(err, "%s name '%.*s...' is too long (at most %zu bytes)", what,
                         MATERIAL_NAME_MAX / 2, name, max - 1);
    const char *blank = " \t\v\f";
    for (size_t i = 0; i < len; i++) {
        unsigned char c = (unsigned char)name[i];
        if (c == '#' || c == '\n' || c == '\r' || (one_word && strchr(blank, c)))
            return error_set(err, "%s name '%s' has a character an %s file cannot hold", what,
                             name, strcmp(what, "material") == 0 ? "MTL" : "OBJ");
    }
    if (strchr(blank, name[0]) || strchr(blank, name[len - 1]))
        return error_set(err, "%s name '%s' starts or ends with white space", what, name);
    return true;
}

static bool material_name_ok(const char *name, Error *err)
{
    return name_ok("material", name, MATERIAL_NAME_MAX, false, err);
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
    f->names = -1;
    memcpy(m->corners + m->ncorners, vertex_indices, sizeof *vertex_indices * (size_t)n);
    m->ncorners += n;
    m->ntris += triangulate_polygon(pts, n, m->tris + m->ntris, &f->convex);
    if (pts != small)
        free(pts);
    return m->nfaces++;
}

/* What a name costs in memory, its pointer included: counted against
 * MESH_MAX_NAME_BYTES, so that a file of a million `g` lines of 64 names each
 * meets an error, not an exhausted machine. */
static long long name_cost(const char *name)
{
    return (long long)(strlen(name) + 1 + sizeof(char *));
}

/* A copy of name, counted against MESH_MAX_NAME_BYTES; NULL with err set. */
static char *copy_name(Mesh *m, const char *name, Error *err)
{
    size_t n = strlen(name) + 1;
    if (m->name_bytes + name_cost(name) > MESH_MAX_NAME_BYTES) {
        error_set(err, "too many object and group names (at most %d bytes in all)",
                  MESH_MAX_NAME_BYTES);
        return NULL;
    }
    char *copy = malloc(n);
    if (!copy) {
        error_set(err, "out of memory");
        return NULL;
    }
    memcpy(copy, name, n);
    m->name_bytes += name_cost(name);
    return copy;
}

static bool names_ok(const Mesh *m, const char *object, const char *const *groups,
                     int ngroups, Error *err)
{
    if (ngroups < 0 || ngroups > MESH_MAX_GROUPS)
        return error_set(err, "a face is in at most %d groups, not %d", MESH_MAX_GROUPS,
                         ngroups);
    if (m->nsets >= MESH_MAX_NAME_SETS)
        return error_set(err, "too many object and group changes (at most %d)",
                         MESH_MAX_NAME_SETS);
    if (object && !name_ok("object", object, MESH_NAME_MAX, false, err))
        return false;
    for (int k = 0; k < ngroups; k++)
        if (!name_ok("group", groups[k], MESH_NAME_MAX, true, err))
            return false;
    return true;
}

static void free_set(Mesh *m, NameSet *set)
{
    if (set->object)
        m->name_bytes -= name_cost(set->object);
    free(set->object);
    for (int k = 0; k < set->ngroups; k++) {
        m->name_bytes -= name_cost(set->groups[k]);
        free(set->groups[k]);
    }
    free(set->groups);
}

int mesh_add_names(Mesh *m, const char *object, const char *const *groups, int ngroups,
                   Error *err)
{
    if (!names_ok(m, object, groups, ngroups, err) ||
        !reserve((void **)&m->sets, &m->cap_sets, m->nsets + 1, sizeof *m->sets, err))
        return -1;
    NameSet set = {0};
    bool ok = ngroups == 0 || (set.groups = malloc(sizeof *set.groups * (size_t)ngroups));
    if (!ok)
        error_set(err, "out of memory");
    if (ok && object)
        ok = (set.object = copy_name(m, object, err)) != NULL;
    for (int k = 0; ok && k < ngroups; k++) {
        bool repeated = false;
        for (int j = 0; j < set.ngroups && !repeated; j++)
            repeated = strcmp(set.groups[j], groups[k]) == 0;
        if (!repeated && (ok = (set.groups[set.ngroups] = copy_name(m, groups[k], err)) != NULL))
            set.ngroups++;
    }
    if (!ok) {
        free_set(m, &set);
        return -1;
    }
    m->sets[m->nsets] = set;
    return m->nsets++;
}

