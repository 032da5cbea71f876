/* lesson.c: see lesson.h. */
#include "lesson.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "compare.h"
#include "file.h"

/* Before anything is drawn: no output may replace a .mtl file the OBJ read
 * (known only once it is loaded: a usage error, as for --obj itself),
 * --id-out must be able to number every face of the mesh, and every output
 * must be writable (both failures while running, as --steps refusing a mesh
 * of too many faces is). */
static int check_outputs(Run *run)
{
    enum { SHARED = 6, MAX = SHARED + CLI_MAX_EXTRA };
    const Options *o = &run->opt;
    char diff[PATH_TEXT_MAX];
    bool has_diff = o->compare && o->out && !is_stdout_name(o->out) &&
                    compare_diff_path(o->out, diff, sizeof diff);
    const char *name[MAX] = {"--out", "--depth-out", "--overdraw-out", "--id-out", "--world-out",
                             "the diff picture of --out"};
    const char *path[MAX] = {o->out, o->depth_out, o->overdraw_out, o->id_out, o->world_out,
                             has_diff ? diff : NULL};
    int n = SHARED;
    const Extras *x = run->lesson->extras; /* and the lesson's own outputs */
    for (int i = 0; x && i < x->n_flags && i < CLI_MAX_EXTRA; i++)
        if (x->flags[i].output && o->extra[i]) {
            name[n] = x->flags[i].flag;
            path[n++] = o->extra[i];
        }
    const Mesh *m = &run->render.mesh;
    for (int k = 0; k < m->nlibraries; k++) {
        const char *lib = m->libraries[k];
        for (int i = 0; i < n; i++)
            if (path[i] && !is_stdout_name(path[i]) && same_file(path[i], lib)) {
                error_set(&run->err, "%s names %s, a material library that %s reads", name[i],
                          path[i], o->obj);
                return EXIT_USAGE;
            }
        if (o->steps_dir && is_step_picture(lib, o->steps_dir)) {
            error_set(&run->err, "--steps would write %s, a material library that %s reads",
                      lib, o->obj);
            return EXIT_USAGE;
        }
    }
    if (o->id_out && !face_ids_fit(m->nfaces, &run->err))
        return EXIT_RUN_FAILED;
    for (int i = 0; i < n; i++)
        if (path[i] && !output_check(path[i], &run->err))
            return EXIT_RUN_FAILED;
    if (o->steps_dir && !output_dir_check(o->steps_dir, &run->err))
        return EXIT_RUN_FAILED;
    return EXIT_OK;
}

int run_load(Run *run, const Lesson *lesson, int argc, char **argv)
{
    signals_begin(lesson->program); /* a signal from now on prints one line */
    memset(run, 0, sizeof *run);
    run->lesson = lesson;
    run->rasterizer = *lesson->rasterizer;
    run->rz = &run->rasterizer;
    run->rule = &lesson->depth_rule;
    snprintf(run->default_out, sizeof run->default_out, "out/%s.png", lesson->program);
    const Extras *x = lesson->extras;
    LessonCli cli = {
        .program = lesson->program,
        .purpose = lesson->purpose,
        .groups = CLI_ALL_3D,
        .extra = x ? x->flags : NULL,
        .n_extra = x ? x->n_flags : 0,
        .defaults = {.out = run->default_out, .width = 800, .height = 600,
                     .scene = lesson->scene, .shade = SHADE_FLAT},
    };
    int status = cli_parse(&cli, argc, argv, &run->opt);
    if (status != CLI_CONTINUE)
        return status;
    if (x && x->choose && !x->choose(run, &run->err))
        return error_report(lesson->program, &run->err, EXIT_USAGE);
    status = render_load(&run->render, &run->opt, &run->err);
    if (status != EXIT_OK)
        return error_report(lesson->program, &run->err, status);
    render_print_warnings(&run->render, lesson->program);
    status = check_outputs(run);
    if (status != EXIT_OK) {
        render_free(&run->render);
        return error_report(lesson->program, &run->err, status);
    }
    if (!target_init(&run->target, run->opt.width, run->opt.height, &run->err)) {
        render_free(&run->render);
        return error_report(lesson->program, &run->err, EXIT_RUN_FAILED);
    }
    run->status = RUN_GO; /* until run_report gives the run's status */
    return RUN_GO;
}

static bool fail(Run *run)
{
    run->status = EXIT_RUN_FAILED;
    return false;
}

/* --steps writes the cleared buffer first, then a frame after every face. */
bool run_draw(Run *run)
{
    output_set_begin(); /* every file of the run is published by run_end, or none */
    if (!inspect_begin(&run->inspection, &run->render, &run->target, run->rz, run->rule,
                       &run->opt, &run->err))
        return fail(run);
    bool ok = run->draw ? run->draw(run, &run->err)
                        : render_faces(&run->render, &run->target, run->rz, NULL, 0,
                                       inspect_after_face, &run->inspection, &run->err);
    return ok || fail(run);
}

/* The shared outputs say "wrote" themselves (render_write); a lesson's own
 * are listed under the summary, each once its extra has written it. */
bool run_write(Run *run)
{
    bool ok = render_write(&run->render, &run->target, run->rz, &run->opt, &run->err) &&
              (!run->after_write || run->after_write(run, &run->err));
    const Extras *x = run->lesson->extras;
    for (int i = 0; ok && x && i < x->n_flags && i < CLI_MAX_EXTRA; i++)
        if (x->flags[i].output && run->opt.extra[i])
            run_note(run, "  wrote %s", run->opt.extra[i]);
    return ok || fail(run);
}

/* The summary goes to standard output, or to standard error when the picture
 * went there (--out -). */
bool run_report(Run *run)
{
    bool to_stderr = is_stdout_name(run->opt.out);
    int saved = to_stderr ? stdout_to_stderr_begin() : -1;
    render_print_summary(stdout, run->lesson->program, &run->render, &run->target, &run->opt);
    fputs(run->note, stdout);
    if (run->lesson->report)
        run->lesson->report(&run->target, run->rz->state);
    run->status = inspect_report(stdout, &run->inspection, &run->target, &run->err);
    if (to_stderr)
        stdout_to_stderr_end(saved);
    return run->status != EXIT_RUN_FAILED;
}

int run_end(Run *run)
{
    target_free(&run->target);
    render_free(&run->render);
    /* A run that ends before its report has failed: a lesson's own set-up
     * (its buffers, say) stopped it, with the error it recorded. */
    if (run->status == RUN_GO) {
        run->status = EXIT_RUN_FAILED;
        if (run->err.msg[0] == '\0')
            error_set(&run->err, "the run ended before it was drawn and reported");
    }
    /* Lost output on standard output is a failure too, and then no file is
     * published either: the run is all or nothing. */
    if (run->status != EXIT_RUN_FAILED && !stdout_flush(&run->err))
        run->status = EXIT_RUN_FAILED;
    if (run->status == EXIT_RUN_FAILED)
        output_set_abort();
    else if (!output_set_publish(&run->err))
        run->status = EXIT_RUN_FAILED;
    if (run->status == EXIT_RUN_FAILED)
        return error_report(run->lesson->program, &run->err, run->status);
    return run->status;
}

void run_note(Run *run, const char *fmt, ...)
{
    size_t used = strlen(run->note);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(run->note + used, sizeof run->note - used, fmt, ap);
    va_end(ap);
    used = strlen(run->note);
    if (used + 1 < sizeof run->note)
        strcat(run->note, "\n");
}
