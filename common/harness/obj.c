/* obj.c: reading and writing Wavefront OBJ files and their MTL materials.
 *
 * Reading, step by step:
 *   next_line       one line at a time, of any length, into a buffer that grows;
 *                   a NUL byte is an error, '#' starts a comment
 *   next_word       the words of a line, split at white space (\t \v \f \r too,
 *                   so CRLF files read as they should)
 *   read_vertex     v x y z [w]            finite numbers, |x| <= OBJ_MAX_COORDINATE
 *   read_face       f v v/vt v//vn v/vt/vn positive or negative (relative) indices
 *   use_material    usemtl NAME            a name the .mtl files defined
 *   read_libraries  mtllib A.mtl ...       newmtl NAME and Kd r g b from each
 *   name_object     o NAME                 the object of the faces that follow
 *   name_groups     g A B ...              their groups (a bare g: none)
 * Anything else is accepted (vt, vn, s) or ignored with a warning, so
 * nothing is dropped silently. Every message starts "file:line: ".
 *
 * The mesh is built in a fresh Mesh and handed over only when the whole file
 * was read: a caller never sees half a mesh. */
#include "mesh_build.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "file.h"

/* Warnings kept in m->warnings; one more line then says how many were not. */
#define MAX_WARNINGS_KEPT 20
/* Distinct mtllib files read per OBJ file. */
#define MAX_MATERIAL_LIBRARIES 16
/* Words quoted in a message are cut to this many characters. */
#define QUOTE_MAX 40
/* "v x y z", "v x y z w", and "v x y z r g b" (vertex colours, as some
 * programs write them). */
#define VERTEX_NUMBERS_MAX 7

static const char BLANKS[] = " \t\v\f\r";

/* ---- Lines and words --------------------------------------------------- */

typedef struct {
    const char *text;
    size_t len, pos;
    const char *name; /* the file, as the caller named it, for messages */
    long number;      /* of the current line, from 1 */
    char *buf;        /* the current line, NUL-terminated, comment removed */
    size_t cap;
} Lines;

static bool fail_at(const Lines *l, Error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* "file:line: what" */
static bool fail_at(const Lines *l, Error *err, const char *fmt, ...)
{
    char what[ERROR_MSG_MAX];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return error_set(err, "%s:%ld: %s", l->name, l->number, what);
}

/* 1: a line is in l->buf; 0: the text is over; -1: an error (err set). */
static int next_line(Lines *l, Error *err)
{
    if (l->pos >= l->len)
        return 0;
    const char *start = l->text + l->pos;
    const char *nl = memchr(start, '\n', l->len - l->pos);
    size_t n = nl ? (size_t)(nl - start) : l->len - l->pos;
    l->pos += n + (nl ? 1 : 0);
    l->number++;
    if (memchr(start, '\0', n)) {
        fail_at(l, err, "NUL byte in line");
        return -1;
    }
    if (n + 1 > l->cap) {
        size_t cap = l->cap ? l->cap : 256;
        while (cap < n + 1)
            cap *= 2;
        char *grown = realloc(l->buf, cap);
        if (!grown) {
            fail_at(l, err, "out of memory for a line of %zu bytes", n);
            return -1;
        }
        l->buf = grown;
        l->cap = cap;
    }
    memcpy(l->buf, start, n);
    l->buf[n] = '\0';
    char *comment = strchr(l->buf, '#');
    if (comment)
        *comment = '\0';
    return 1;
}

/* The next word at *cursor, NUL-terminated in place; NULL when none is left. */
static char *next_word(char **cursor)
{
    char *s = *cursor + strspn(*cursor, BLANKS);
    if (*s == '\0') {
        *cursor = s;
        return NULL;
    }
    char *end = s + strcspn(s, BLANKS);
    *cursor = *end ? end + 1 : end;
    *end = '\0';
    return s;
}

static int count_words(const char *s)
{
    int n = 0;
    for (;;) {
        s += strspn(s, BLANKS);
        if (*s == '\0')
            return n;
        if (n < INT_MAX)
            n++;
        s += strcspn(s, BLANKS);
    }
}

/* The rest of the line with white space trimmed from both ends: a name. */
static char *rest_of_line(char *cursor)
{
    char *s = cursor + strspn(cursor, BLANKS);
    size_t n = strlen(s);
    while (n > 0 && strchr(BLANKS, s[n - 1]))
        s[--n] = '\0';
    return s;
}

/* A word for a message, cut short if it is long (a line may be megabytes). */
typedef struct { char s[QUOTE_MAX + 4]; } Quote;

static Quote quote(const char *word)
{
    Quote q;
    size_t n = strlen(word);
    if (n <= QUOTE_MAX)
        memcpy(q.s, word, n + 1);
    else {
        memcpy(q.s, word, QUOTE_MAX);
        strcpy(q.s + QUOTE_MAX, "...");
    }
    return q;
}

/* ---- Numbers and indices ------------------------------------------------ */

/* A finite number no larger than OBJ_MAX_COORDINATE, the whole word. */
static bool read_number(const Lines *l, const char *word, const char *what, double *out,
                        Error *err)
{
    char *end;
    errno = 0;
    double x = strtod(word, &end);
    if (end == word || *end != '\0')
        return fail_at(l, err, "%s '%s' is not a number", what, quote(word).s);
    bool overflowed = isinf(x) && errno == ERANGE; /* 1e999: finite text, too big */
    if (isnan(x) || (isinf(x) && !overflowed))
        return fail_at(l, err, "%s '%s' is not a finite number", what, quote(word).s);
    if (overflowed || fabs(x) > OBJ_MAX_COORDINATE)
        return fail_at(l, err, "%s '%s' is out of range (|x| <= %g)", what, quote(word).s,
                       OBJ_MAX_COORDINATE);
    *out = x;
    return true;
}

/* An OBJ index: 1 .. count from the start, -1 .. -count back from the last one
 * defined so far. Returns the 0-based index in *out. */
static bool read_index(const Lines *l, const char *word, int count, const char *what,
                       int *out, Error *err)
{
    const char *s = word;
    bool negative = *s == '-';
    if (*s == '-' || *s == '+')
        s++;
    if (*s < '0' || *s > '9')
        return fail_at(l, err, "%s '%s' is not an integer", what, quote(word).s);
    long long value = 0;
    bool huge = false;
    for (; *s >= '0' && *s <= '9'; s++) {
        value = value * 10 + (*s - '0');
        if (value > INT_MAX) {
            huge = true; /* keep reading digits; the index is out of range anyway */
            value = INT_MAX;
        }
    }
    if (*s != '\0')
        return fail_at(l, err, "%s '%s' is not an integer", what, quote(word).s);
    if (value == 0 && !huge)
        return fail_at(l, err, "%s %s is invalid (the first is 1, the last is -1)", what,
                       quote(word).s);
    if (huge || value > count) {
        if (count == 0)
            return fail_at(l, err, "%s %s is out of range (none defined yet)", what,
                           quote(word).s);
        return fail_at(l, err, "%s %s is out of range (1 to %d, or -1 to -%d)", what,
                       quote(word).s, count, count);
    }
    *out = negative ? count - (int)value : (int)value - 1;
    return true;
}

/* ---- The reader's state ------------------------------------------------- */

typedef struct {
    const char *name;
    int index;
} NamedMaterial;

typedef struct {
    Mesh *m;
    Lines lines;         /* of the OBJ file */
    const char *mtl_dir; /* NULL: .mtl files are not read */
    int material;        /* set by usemtl, -1 for none */
    int names;           /* set by o and g: index into m->sets, -1 for none */
    int ntexcoords, nnormals;
    NamedMaterial *by_name; /* materials sorted by name, for usemtl */
    int nby_name;
    char *libraries[MAX_MATERIAL_LIBRARIES]; /* mtllib names read already */
    int nlibraries;
    long warnings_not_kept;
    int *face;           /* corner vertex indices of the face being read */
} ObjReader;

static bool warn_at(ObjReader *r, const Lines *l, Error *err, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

static bool keep_warning(Mesh *m, const char *line, Error *err)
{
    char **grown = realloc(m->warnings, sizeof *grown * (size_t)(m->nwarnings + 1));
    char *copy = malloc(strlen(line) + 1);
    if (grown)
        m->warnings = grown;
    if (!grown || !copy) {
        free(copy);
        return error_set(err, "out of memory");
    }
    strcpy(copy, line);
    m->warnings[m->nwarnings++] = copy;
    return true;
}

/* Adds "file:line: what" to m->warnings, the first MAX_WARNINGS_KEPT of them. */
static bool warn_at(ObjReader *r, const Lines *l, Error *err, const char *fmt, ...)
{
    if (r->m->nwarnings >= MAX_WARNINGS_KEPT) {
        r->warnings_not_kept++;
        return true;
    }
    char what[ERROR_MSG_MAX], line[ERROR_MSG_MAX + 64];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    snprintf(line, sizeof line, "%s:%ld: %s", l->name, l->number, what);
    return keep_warning(r->m, line, err);
}

/* ---- Materials ---------------------------------------------------------- */

static int compare_named(const void *a, const void *b)
{
    const NamedMaterial *x = a, *y = b;
    int c = strcmp(x->name, y->name);
    return c ? c : (x->index > y->index) - (x->index < y->index);
}

/* Sorted by name, then by index: a name defined twice finds its first definition. */
static bool index_materials(ObjReader *r, Error *err)
{
    free(r->by_name);
    r->nby_name = 0;
    r->by_name = malloc(sizeof *r->by_name * (size_t)(r->m->nmaterials + 1));
    if (!r->by_name)
        return error_set(err, "out of memory");
    for (int i = 0; i < r->m->nmaterials; i++)
        r->by_name[i] = (NamedMaterial){.name = r->m->materials[i].name, .index = i};
    r->nby_name = r->m->nmaterials;
    qsort(r->by_name, (size_t)r->nby_name, sizeof *r->by_name, compare_named);
    return true;
}

static int find_material(const ObjReader *r, const char *name)
{
    int lo = 0, hi = r->nby_name; /* the first entry not less than name */
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (strcmp(r->by_name[mid].name, name) < 0)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo < r->nby_name && strcmp(r->by_name[lo].name, name) == 0 ? r->by_name[lo].index
                                                                       : -1;
}

/* Kd r g b (or Kd r: grey), each clamped to [0, 1]. */
static bool read_kd(ObjReader *r, const Lines *l, char *cursor, int material, Error *err)
{
    if (material < 0)
        return warn_at(r, l, err, "'Kd' before any 'newmtl' is ignored");
    char *word = next_word(&cursor);
    if (word && (strcmp(word, "spectral") == 0 || strcmp(word, "xyz") == 0))
        return warn_at(r, l, err, "'Kd %s' colours are not supported; the colour is ignored",
                       word);
    double c[3];
    int n = 0;
    for (; word; word = next_word(&cursor)) {
        if (n == 3)
            return fail_at(l, err, "'Kd' takes 3 numbers (r g b), found more");
        if (!read_number(l, word, "Kd value", &c[n++], err))
            return false;
    }
    if (n != 1 && n != 3)
        return fail_at(l, err, "'Kd' takes 3 numbers (r g b), found %d", n);
    if (n == 1)
        c[1] = c[2] = c[0];
    Material *mat = &r->m->materials[material];
    mat->kd = vec3(c[0] < 0 ? 0 : c[0] > 1 ? 1 : c[0], c[1] < 0 ? 0 : c[1] > 1 ? 1 : c[1],
                   c[2] < 0 ? 0 : c[2] > 1 ? 1 : c[2]);
    mat->has_kd = true;
    return true;
}

/* A UTF-8 byte order mark, which some editors put at the start of a text file. */
static const char BYTE_ORDER_MARK[] = "\xef\xbb\xbf";

static void skip_byte_order_mark(const char **text, size_t *len)
{
    size_t n = sizeof BYTE_ORDER_MARK - 1;
    if (*len >= n && memcmp(*text, BYTE_ORDER_MARK, n) == 0) {
        *text += n;
        *len -= n;
    }
}

/* The .mtl files read are inputs of the run: an output must not replace one. */
static bool note_library(Mesh *m, const char *path, Error *err)
{
    char **grown = realloc(m->libraries, ((size_t)m->nlibraries + 1) * sizeof *grown);
    if (!grown)
        return error_set(err, "out of memory");
    m->libraries = grown;
    size_t n = strlen(path) + 1;
    if (!(m->libraries[m->nlibraries] = malloc(n)))
        return error_set(err, "out of memory");
    memcpy(m->libraries[m->nlibraries++], path, n);
    return true;
}

static bool read_mtl_text(ObjReader *r, const char *text, size_t len, const char *name,
                          Error *err)
{
    skip_byte_order_mark(&text, &len);
    Lines l = {.text = text, .len = len, .name = name};
    int material = -1, got;
    bool ok = true;
    while (ok && (got = next_line(&l, err)) > 0) {
        char *cursor = l.buf;
        char *word = next_word(&cursor);
        if (!word)
            continue;
        if (strcmp(word, "newmtl") == 0) {
            char *mat_name = rest_of_line(cursor);
            Error why;
            if (*mat_name == '\0')
                ok = fail_at(&l, err, "'newmtl' needs a material name");
            else if ((material = mesh_add_material(r->m, mat_name, vec3(0, 0, 0), &why)) < 0)
                ok = fail_at(&l, err, "%s", why.msg);
            else
                r->m->materials[material].has_kd = false;
        } else if (strcmp(word, "Kd") == 0) {
            ok = read_kd(r, &l, cursor, material, err);
        }
        /* Ka, Ks, Ns, d, illum, map_Kd ...: the lessons use only Kd. */
    }
    free(l.buf);
    return ok && got == 0;
}

static bool read_library(ObjReader *r, const char *lib, Error *err)
{
    const Lines *l = &r->lines;
    for (int i = 0; i < r->nlibraries; i++)
        if (strcmp(r->libraries[i], lib) == 0)
            return true; /* read already */
    if (r->nlibraries == MAX_MATERIAL_LIBRARIES)
        return warn_at(r, l, err, "material library '%s' ignored (at most %d libraries)",
                       quote(lib).s, MAX_MATERIAL_LIBRARIES);
    char *path = malloc(strlen(r->mtl_dir) + strlen(lib) + 2);
    char *copy = malloc(strlen(lib) + 1);
    if (!path || !copy) {
        free(path);
        free(copy);
        return error_set(err, "out of memory");
    }
    strcpy(copy, lib);
    r->libraries[r->nlibraries++] = copy;
    /* Relative to the OBJ file's directory; "." adds nothing to the name. */
    if (lib[0] == '/' || strcmp(r->mtl_dir, ".") == 0)
        strcpy(path, lib);
    else
        sprintf(path, "%s/%s", r->mtl_dir, lib);

    bool ok;
    struct stat st;
    char *text = NULL;
    size_t len = 0;
    Error why;
    int found = stat(path, &st);
    if (found != 0 && (errno == ENOENT || errno == ENOTDIR))
        ok = warn_at(r, l, err, "material library '%s' not found", quote(lib).s);
    else if (found == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
        /* A pipe would wait for a writer forever, /dev/zero never ends. */
        ok = warn_at(r, l, err, "material library '%s' is not a regular file; ignored",
                     quote(lib).s);
    else if (!read_file(path, OBJ_MAX_BYTES, &text, &len, &why))
        ok = errno == ENOMEM /* not the file's fault: the run fails, colours are not lost */
                 ? error_set(err, "%s", why.msg)
                 : warn_at(r, l, err, "material library '%s' not read: %s", quote(lib).s, why.msg);
    else
        ok = note_library(r->m, path, err) && read_mtl_text(r, text, len, path, err) &&
             index_materials(r, err);
    free(text);
    free(path);
    return ok;
}

static bool read_libraries(ObjReader *r, char *cursor, Error *err)
{
    if (!r->mtl_dir)
        return true; /* the caller asked for no .mtl files */
    int n = 0;
    for (char *lib = next_word(&cursor); lib; lib = next_word(&cursor), n++)
        if (!read_library(r, lib, err))
            return false;
    if (n == 0)
        return warn_at(r, &r->lines, err, "'mtllib' without a file name is ignored");
    return true;
}

/* usemtl NAME: the faces that follow get that material. A bare "usemtl" (as
 * mesh_write_obj writes it) means no material. */
static bool use_material(ObjReader *r, char *cursor, Error *err)
{
    const char *name = rest_of_line(cursor);
    r->material = *name ? find_material(r, name) : -1;
    if (*name && r->material < 0)
        return warn_at(r, &r->lines, err,
                       "material '%s' is not defined; the faces that follow get none",
                       quote(name).s);
    return true;
}

/* ---- Objects and groups ------------------------------------------------ */

/* The faces that follow are in object (NULL: none) and groups: a new set of
 * names, or none at all. */
static bool set_names(ObjReader *r, const char *object, const char *const *groups,
                      int ngroups, Error *err)
{
    Error why;
    r->names = object || ngroups > 0 ? mesh_add_names(r->m, object, groups, ngroups, &why) : -1;
    if (r->names < 0 && (object || ngroups > 0))
        return fail_at(&r->lines, err, "%s", why.msg);
    return true;
}

/* o NAME (the rest of the line): the groups stay as they are. */
static bool name_object(ObjReader *r, char *cursor, Error *err)
{
    const char *name = rest_of_line(cursor);
    const NameSet *now = r->names >= 0 ? &r->m->sets[r->names] : NULL;
    return set_names(r, *name ? name : NULL, now ? (const char *const *)now->groups : NULL,
                     now ? now->ngroups : 0, err);
}

/* g A B ...: the object stays as it is. */
static bool name_groups(ObjReader *r, char *cursor, Error *err)
{
    int n = count_words(cursor);
    if (n > MESH_MAX_GROUPS)
        return fail_at(&r->lines, err, "'g' names %d groups (at most %d)", n, MESH_MAX_GROUPS);
    const char *groups[MESH_MAX_GROUPS];
    for (int k = 0; k < n; k++)
        groups[k] = next_word(&cursor);
    const char *object = r->names >= 0 ? r->m->sets[r->names].object : NULL;
    return set_names(r, object, groups, n, err);
}

/* ---- Geometry ----------------------------------------------------------- */

static bool read_vertex(ObjReader *r, char *cursor, Error *err)
{
    const Lines *l = &r->lines;
    double x[VERTEX_NUMBERS_MAX];
    int n = 0;
    for (char *word = next_word(&cursor); word; word = next_word(&cursor)) {
        if (n == VERTEX_NUMBERS_MAX)
            return fail_at(l, err, "'v' takes 3 or 4 numbers (x y z [w]), found more than %d",
                           VERTEX_NUMBERS_MAX);
        if (!read_number(l, word, "vertex coordinate", &x[n++], err))
            return false;
    }
    if (n != 3 && n != 4 && n != 6 && n != 7)
        return fail_at(l, err, "'v' takes 3 or 4 numbers (x y z [w]), found %d", n);
    if (n >= 6 && !warn_at(r, l, err, "vertex colours are ignored"))
        return false;
    /* w only weighs rational curves: a polygon's vertex is (x, y, z). */
    Error why;
    if (mesh_add_vertex(r->m, vec3(x[0], x[1], x[2]), &why) < 0)
        return fail_at(l, err, "%s", why.msg);
    return true;
}

/* vt and vn are counted, so that face corners can be checked, and not kept. */
static bool count_attribute(ObjReader *r, int *count, const char *what, Error *err)
{
    if (*count >= MESH_MAX_VERTICES)
        return fail_at(&r->lines, err, "too many %s (at most %d)", what, MESH_MAX_VERTICES);
    ++*count;
    return true;
}

/* One corner: v, v/vt, v//vn or v/vt/vn. */
static bool read_corner(ObjReader *r, char *word, int *vertex, Error *err)
{
    const Lines *l = &r->lines;
    char *slash1 = strchr(word, '/');
    char *slash2 = slash1 ? strchr(slash1 + 1, '/') : NULL;
    bool bad_form = word[0] == '/' || (slash2 && strchr(slash2 + 1, '/')) ||
                    (slash1 && !slash2 && slash1[1] == '\0') || (slash2 && slash2[1] == '\0');
    if (bad_form)
        return fail_at(l, err, "face corner '%s' is not v, v/vt, v//vn or v/vt/vn",
                       quote(word).s);
    char *vt = NULL, *vn = NULL;
    if (slash1) {
        *slash1 = '\0';
        vt = slash1 + 1;
    }
    if (slash2) {
        *slash2 = '\0';
        vn = slash2 + 1;
    }
    int ignored;
    return read_index(l, word, r->m->nverts, "vertex index", vertex, err) &&
           (!vt || !*vt ||
            read_index(l, vt, r->ntexcoords, "texture coordinate index", &ignored, err)) &&
           (!vn || read_index(l, vn, r->nnormals, "normal index", &ignored, err));
}

static bool read_face(ObjReader *r, char *cursor, Error *err)
{
    const Lines *l = &r->lines;
    int n = count_words(cursor);
    if (n < 3)
        return fail_at(l, err, "face has %d corners (at least 3 needed)", n);
    if (n > MESH_MAX_FACE_VERTICES)
        return fail_at(l, err, "face has %d corners (at most %d)", n, MESH_MAX_FACE_VERTICES);
    for (int i = 0; i < n; i++)
        if (!read_corner(r, next_word(&cursor), &r->face[i], err))
            return false;
    Error why;
    int face = mesh_add_face(r->m, r->face, n, r->material, &why);
    if (face < 0)
        return fail_at(l, err, "%s", why.msg);
    r->m->faces[face].names = r->names;
    return true;
}

/* ---- Statements --------------------------------------------------------- */

static bool is_one_of(const char *word, const char *const *list)
{
    for (; *list; list++)
        if (strcmp(word, *list) == 0)
            return true;
    return false;
}

/* Smoothing groups: accepted, with nothing to do. */
static const char *const NOTHING_TO_DO[] = {"s", NULL};

static bool read_statement(ObjReader *r, Error *err)
{
    char *cursor = r->lines.buf;
    char *word = next_word(&cursor);
    if (!word)
        return true; /* a blank line or a comment */
    if (strcmp(word, "v") == 0)
        return read_vertex(r, cursor, err);
    if (strcmp(word, "f") == 0)
        return read_face(r, cursor, err);
    if (strcmp(word, "vt") == 0)
        return count_attribute(r, &r->ntexcoords, "texture coordinates", err);
    if (strcmp(word, "vn") == 0)
        return count_attribute(r, &r->nnormals, "normals", err);
    if (strcmp(word, "usemtl") == 0)
        return use_material(r, cursor, err);
    if (strcmp(word, "mtllib") == 0)
        return read_libraries(r, cursor, err);
    if (strcmp(word, "o") == 0)
        return name_object(r, cursor, err);
    if (strcmp(word, "g") == 0)
        return name_groups(r, cursor, err);
    if (is_one_of(word, NOTHING_TO_DO))
        return true;
    /* l, p, vp, curv, surf, ... and anything unknown. */
    return warn_at(r, &r->lines, err, "'%s' statements are ignored", quote(word).s);
}

static bool read_obj(ObjReader *r, Error *err)
{
    int got;
    while ((got = next_line(&r->lines, err)) > 0)
        if (!read_statement(r, err))
            return false;
    if (got < 0)
        return false;
    if (r->m->nfaces == 0)
        return error_set(err, "%s: no faces", r->lines.name);
    if (r->warnings_not_kept > 0) {
        char line[ERROR_MSG_MAX];
        snprintf(line, sizeof line, "%s: %ld more warnings not shown", r->lines.name,
                 r->warnings_not_kept);
        return keep_warning(r->m, line, err);
    }
    return true;
}

bool mesh_parse_obj(Mesh *m, const char *text, size_t len, const char *name,
                    const char *mtl_dir, Error *err)
{
    if (len > OBJ_MAX_BYTES)
        return error_set(err, "%s: larger than %zu bytes", name, OBJ_MAX_BYTES);
    skip_byte_order_mark(&text, &len);
    Mesh fresh;
    mesh_init(&fresh);
    ObjReader r;
    memset(&r, 0, sizeof r);
    r.m = &fresh;
    r.lines = (Lines){.text = text, .len = len, .name = name};
    r.mtl_dir = mtl_dir;
    r.material = -1;
    r.names = -1;
    r.face = malloc(sizeof *r.face * MESH_MAX_FACE_VERTICES);
    bool ok = r.face ? read_obj(&r, err) : error_set(err, "out of memory");
    free(r.face);
    free(r.lines.buf);
    free(r.by_name);
    for (int i = 0; i < r.nlibraries; i++)
        free(r.libraries[i]);
    if (!ok) {
        mesh_free(&fresh);
        return false;
    }
    mesh_free(m);
    *m = fresh;
    return true;
}

/* The directory part of path: "a/b.obj" -> "a", "b.obj" -> ".", "/b.obj" -> "/". */
static char *directory_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 1;
    if (slash == path)
        n = 1;
    char *dir = malloc(n + 1);
    if (dir) {
        memcpy(dir, slash ? path : ".", n);
        dir[n] = '\0';
    }
    return dir;
}

bool mesh_load_obj(Mesh *m, const char *path, Error *err)
{
    char *text, *dir = directory_of(path);
    size_t len;
    if (!dir)
        return error_set(err, "out of memory");
    bool ok = read_file(path, OBJ_MAX_BYTES, &text, &len, err);
    if (ok) {
        ok = mesh_parse_obj(m, text, len, path, dir, err);
        free(text);
    }
    free(dir);
    return ok;
}

/* ---- Writing ------------------------------------------------------------ */

/* "x.obj" -> "x.mtl"; any other name gets ".mtl" added. */
static char *mtl_path_for(const char *path)
{
    size_t n = strlen(path);
    const char *ext = ".obj";
    if (n >= 4 && strcmp(path + n - 4, ext) == 0)
        n -= 4;
    char *mtl = malloc(n + 5);
    if (mtl) {
        memcpy(mtl, path, n);
        strcpy(mtl + n, ".mtl");
    }
    return mtl;
}

static const char *base_name(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* The shortest of %.15g, %.16g, %.17g that reads back as the same double:
 * 0.5 stays "0.5", and no vertex moves on the way through a file. */
static void write_double(FILE *fp, double x)
{
    char text[32];
    for (int digits = 15; digits <= 17; digits++) {
        snprintf(text, sizeof text, "%.*g", digits, x);
        if (strtod(text, NULL) == x)
            break;
    }
    fprintf(fp, " %s", text);
}

static bool same_name(const char *a, const char *b)
{
    return a == b || (a && b && strcmp(a, b) == 0);
}

/* o and g lines where the names of the faces change from `from` to `to`
 * (NULL: no names). */
static void write_names(FILE *fp, const NameSet *from, const NameSet *to)
{
    static const NameSet NONE = {0};
    from = from ? from : &NONE;
    to = to ? to : &NONE;
    if (!same_name(from->object, to->object))
        fprintf(fp, "o%s%s\n", to->object ? " " : "", to->object ? to->object : "");
    bool same_groups = from->ngroups == to->ngroups;
    for (int k = 0; same_groups && k < to->ngroups; k++)
        same_groups = strcmp(from->groups[k], to->groups[k]) == 0;
    if (same_groups)
        return;
    fputc('g', fp);
    for (int k = 0; k < to->ngroups; k++)
        fprintf(fp, " %s", to->groups[k]);
    fputc('\n', fp);
}

static bool write_mtl(const Mesh *m, const char *mtl_path, Error *err)
{
    AtomicFile f;
    if (!atomic_open(&f, mtl_path, err))
        return false;
    fprintf(f.fp, "# %d materials\n", m->nmaterials);
    for (int i = 0; i < m->nmaterials; i++) {
        const Material *mat = &m->materials[i];
        fprintf(f.fp, "newmtl %s\n", mat->name);
        if (mat->has_kd) {
            fputs("Kd", f.fp);
            write_double(f.fp, mat->kd.x);
            write_double(f.fp, mat->kd.y);
            write_double(f.fp, mat->kd.z);
            fputc('\n', f.fp);
        }
    }
    return atomic_commit(&f, err);
}

bool obj_path_is_stream(const char *path)
{
    struct stat st, out;
    if (is_stdout_name(path))
        return true;
    if (stat(path, &st) != 0)
        return false;
    return (!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) ||
           (fstat(STDOUT_FILENO, &out) == 0 && out.st_dev == st.st_dev && out.st_ino == st.st_ino);
}

static bool write_obj(const Mesh *m, const char *path, const char *mtl_path, Error *err)
{
    AtomicFile f;
    if (!atomic_open(&f, path, err))
        return false;
    fprintf(f.fp, "# %d vertices, %d faces\n", m->nverts, m->nfaces);
    if (mtl_path)
        fprintf(f.fp, "mtllib %s\n", base_name(mtl_path));
    for (int i = 0; i < m->nverts; i++) {
        fputc('v', f.fp);
        write_double(f.fp, m->verts[i].x);
        write_double(f.fp, m->verts[i].y);
        write_double(f.fp, m->verts[i].z);
        fputc('\n', f.fp);
    }
    int material = -1;
    const NameSet *names = NULL;
    for (int i = 0; i < m->nfaces; i++) {
        const Face *face = &m->faces[i];
        const NameSet *face_names = face->names >= 0 ? &m->sets[face->names] : NULL;
        write_names(f.fp, names, face_names);
        names = face_names;
        if (mtl_path && face->material != material) {
            material = face->material;
            fprintf(f.fp, "usemtl%s%s\n", material >= 0 ? " " : "",
                    material >= 0 ? m->materials[material].name : "");
        }
        fputc('f', f.fp);
        for (int k = 0; k < face->count; k++)
            fprintf(f.fp, " %d", m->corners[face->first + k] + 1);
        fputc('\n', f.fp);
    }
    return atomic_commit(&f, err);
}

/* The .mtl and the OBJ are one output set: both are published, or neither
 * (a failed OBJ leaves no new .mtl, and an existing one keeps its bytes). A
 * .mtl that is the OBJ under another name (a link) is refused: one file
 * cannot hold both. */
bool mesh_write_obj(const Mesh *m, const char *path, Error *err)
{
    char *mtl_path = NULL;
    if (m->nmaterials > 0 && !obj_path_is_stream(path)) {
        mtl_path = mtl_path_for(path);
        if (!mtl_path)
            return error_set(err, "out of memory");
        if (same_file(mtl_path, path)) {
            error_set(err, "cannot write %s: its material library %s is the same file", path,
                      mtl_path);
            free(mtl_path);
            return false;
        }
    }
    bool own_set = !output_set_open();
    if (own_set)
        output_set_begin();
    bool ok = (!mtl_path || write_mtl(m, mtl_path, err)) && write_obj(m, path, mtl_path, err);
    free(mtl_path);
    if (own_set) {
        if (ok)
            ok = output_set_publish(err);
        else
            output_set_abort();
    }
    return ok;
}
