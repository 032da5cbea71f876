/* gl.c: see gl.h. */
#define GL_GLEXT_PROTOTYPES 1
#include "gl.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <stdlib.h>
#include <time.h>

const char *const FORMAT_NAMES[3] = {"unorm16", "unorm24", "float32"};

const char *const MAPPING_NAMES[3] = {"standard", "reversed", "gl"};

const char *const ORIENT_NAMES[4] = {"flip-y", "upper-left", "both", "rows"};
static const GLenum FORMAT_GL[3] = {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
                                    GL_DEPTH_COMPONENT32F};

static bool egl_fail(const char *what, Error *err)
{
    return error_set(err, "%s failed (EGL error 0x%x): is Mesa installed? "
                          "(sh tools/ensure-deps.sh --gpu)", what, (unsigned)eglGetError());
}

/* llvmpipe, whatever GPU the machine has, unless the environment says otherwise. */
bool gpu_open(Gpu *gpu, Error *err)
{
    setenv("EGL_PLATFORM", "surfaceless", 0);
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 0);
    setenv("GALLIUM_DRIVER", "llvmpipe", 0);
    PFNEGLGETPLATFORMDISPLAYEXTPROC get_display =
        (PFNEGLGETPLATFORMDISPLAYEXTPROC)eglGetProcAddress("eglGetPlatformDisplayEXT");
    gpu->display = get_display
                       ? get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, NULL)
                       : eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (gpu->display == EGL_NO_DISPLAY)
        return egl_fail("eglGetPlatformDisplay(surfaceless)", err);
    if (!eglInitialize(gpu->display, NULL, NULL)) {
        gpu->display = EGL_NO_DISPLAY;
        return egl_fail("eglInitialize", err);
    }
    if (!eglBindAPI(EGL_OPENGL_API))
        return egl_fail("eglBindAPI(OpenGL)", err);
    const EGLint attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    gpu->context = eglCreateContext(gpu->display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attribs);
    if (gpu->context == EGL_NO_CONTEXT)
        return egl_fail("eglCreateContext(OpenGL 4.5 core, no config)", err);
    if (!eglMakeCurrent(gpu->display, EGL_NO_SURFACE, EGL_NO_SURFACE, gpu->context))
        return egl_fail("eglMakeCurrent(no surface)", err);
    return true;
}

void gpu_close(Gpu *gpu)
{
    if (gpu->context && gpu->context != EGL_NO_CONTEXT) {
        glDeleteFramebuffers(1, &gpu->fbo);
        glDeleteRenderbuffers(1, &gpu->colour);
        glDeleteRenderbuffers(1, &gpu->depth);
        glDeleteProgram(gpu->program);
        glDeleteBuffers(2, gpu->buffers);
        glDeleteVertexArrays(1, &gpu->vao);
        eglMakeCurrent(gpu->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
        eglDestroyContext(gpu->display, gpu->context);
    }
    /* No eglTerminate: it unloads Mesa's driver but keeps a few of its blocks,
     * which LeakSanitizer (make sanitize) then reports as leaks of an unknown
     * module. The display stays reachable until exit, which frees it all. */
    eglReleaseThread();
}

static const char *const VERTEX_SHADER =
    "#version 330 core\n"
    "layout(location = 0) in vec4 clip;\n"
    "layout(location = 1) in int face;\n"
    "flat out int v_face;\n"
    "void main() { gl_Position = clip; v_face = face; }\n";

/* face + 1 as 24-bit RGB, big-endian: k / 255 stores exactly k in RGBA8. */
static const char *const FRAGMENT_SHADER =
    "#version 330 core\n"
    "flat in int v_face;\n"
    "out vec4 colour;\n"
    "void main() {\n"
    "    int id = v_face + 1;\n"
    "    colour = vec4(float((id >> 16) & 255), float((id >> 8) & 255), float(id & 255),\n"
    "                  255.0) / 255.0;\n"
    "}\n";

static GLuint compile(GLenum kind, const char *source, Error *err)
{
    GLuint s = glCreateShader(kind);
    glShaderSource(s, 1, &source, NULL);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[512] = "";
        glGetShaderInfoLog(s, sizeof log, NULL, log);
        error_set(err, "shader compile failed: %s", log);
        glDeleteShader(s);
        return 0;
    }
    return s;
}

/* The program, the framebuffer (RGBA8 + the depth format) and the vertices. */
bool gpu_prepare(Gpu *gpu, const GpuSetup *g, int width, int height,
                        const Vertices *v, Error *err)
{
    GLint max_side = 0;
    glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_side);
    if (width > max_side || height > max_side)
        return error_set(err, "%dx%d is more than this GPU's largest framebuffer, %d", width,
                         height, (int)max_side);
    GLuint vs = compile(GL_VERTEX_SHADER, VERTEX_SHADER, err);
    GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, FRAGMENT_SHADER, err) : 0;
    if (!fs) {
        glDeleteShader(vs);
        return false;
    }
    gpu->program = glCreateProgram();
    glAttachShader(gpu->program, vs);
    glAttachShader(gpu->program, fs);
    glLinkProgram(gpu->program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint linked = 0;
    glGetProgramiv(gpu->program, GL_LINK_STATUS, &linked);
    if (!linked)
        return error_set(err, "shader link failed");

    glGenRenderbuffers(1, &gpu->colour);
    glBindRenderbuffer(GL_RENDERBUFFER, gpu->colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    glGenRenderbuffers(1, &gpu->depth);
    glBindRenderbuffer(GL_RENDERBUFFER, gpu->depth);
    glRenderbufferStorage(GL_RENDERBUFFER, FORMAT_GL[g->format], width, height);
    glGenFramebuffers(1, &gpu->fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, gpu->fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, gpu->colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, gpu->depth);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        return error_set(err, "the %dx%d framebuffer with %s depth is incomplete", width, height,
                         FORMAT_NAMES[g->format]);

    glGenVertexArrays(1, &gpu->vao);
    glBindVertexArray(gpu->vao);
    glGenBuffers(2, gpu->buffers);
    glBindBuffer(GL_ARRAY_BUFFER, gpu->buffers[0]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)v->n * 4 * sizeof *v->pos), v->pos,
                 GL_STATIC_DRAW);
    glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, gpu->buffers[1]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)((size_t)v->n * sizeof *v->id), v->id,
                 GL_STATIC_DRAW);
    glVertexAttribIPointer(1, 1, GL_INT, 0, NULL);
    glEnableVertexAttribArray(1);

    bool upper = g->orient == ORIENT_UPPER_LEFT || g->orient == ORIENT_BOTH;
    bool reversed = g->mapping == MAP_REVERSED;
    glClipControl(upper ? GL_UPPER_LEFT : GL_LOWER_LEFT,
                  g->mapping == MAP_GL ? GL_NEGATIVE_ONE_TO_ONE : GL_ZERO_TO_ONE);
    glViewport(0, 0, width, height);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DITHER);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(reversed ? GL_GREATER : GL_LESS);
    glClearDepth(reversed ? 0.0 : 1.0);
    glClearColor(0, 0, 0, 0);
    glUseProgram(gpu->program);
    if (glGetError() != GL_NO_ERROR)
        return error_set(err, "OpenGL refused the set-up (error 0x%x)", (unsigned)glGetError());
    return true;
}

double wall_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* glPolygonOffsetClamp, by whichever name this GL has it, or NULL. */
static PFNGLPOLYGONOFFSETCLAMPPROC offset_clamp_function(void)
{
    static const char *const NAMES[] = {"glPolygonOffsetClamp", "glPolygonOffsetClampEXT"};
    for (int k = 0; k < 2; k++) {
        PFNGLPOLYGONOFFSETCLAMPPROC f =
            (PFNGLPOLYGONOFFSETCLAMPPROC)eglGetProcAddress(NAMES[k]);
        if (f)
            return f;
    }
    return NULL;
}

bool gpu_draw_offset(int nverts, const GpuOffset *o, double *seconds, Error *err)
{
    PFNGLPOLYGONOFFSETCLAMPPROC clamp = o->clamp != 0 ? offset_clamp_function() : NULL;
    if (o->clamp != 0 && !clamp)
        return error_set(err, "--offset-clamp: this OpenGL has no glPolygonOffsetClamp");
    double t0 = wall_seconds();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (clamp)
        clamp((GLfloat)o->factor, (GLfloat)o->units, (GLfloat)o->clamp);
    else
        glPolygonOffset((GLfloat)o->factor, (GLfloat)o->units);
    int ntris = nverts / 3;
    for (int first = 0; first < ntris;) { /* runs of triangles alike */
        int end = first + 1;
        while (end < ntris && o->biased[end] == o->biased[first])
            end++;
        if (o->biased[first])
            glEnable(GL_POLYGON_OFFSET_FILL);
        else
            glDisable(GL_POLYGON_OFFSET_FILL);
        glDrawArrays(GL_TRIANGLES, 3 * first, 3 * (end - first));
        first = end;
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    glFinish();
    *seconds = wall_seconds() - t0;
    return glGetError() == GL_NO_ERROR || error_set(err, "OpenGL refused the polygon offset");
}

double gpu_draw(int nverts)
{
    double t0 = wall_seconds();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawArrays(GL_TRIANGLES, 0, nverts);
    glFinish();
    return wall_seconds() - t0;
}

