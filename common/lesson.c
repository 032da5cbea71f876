/* lesson.c: see lesson.h. */
#include "lesson.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

int run_load(Run *run, const Lesson *lesson, int argc, char **argv)
{
    memset(run, 0, sizeof *run);
    run->lesson = lesson;
    run->rz = lesson->rasterizer;
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
    if (!target_init(&run->target, run->opt.width, run->opt.height, &run->err)) {
        render_free(&run->render);
        return error_report(lesson->program, &run->err, EXIT_RUN_FAILED);
    }
    run->status = EXIT_OK;
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
    if (!inspect_begin(&run->inspection, &run->render, &run->target, run->rz, run->rule,
                       &run->opt, &run->err))
        return fail(run);
    bool ok = run->draw ? run->draw(run, &run->err)
                        : render_faces(&run->render, &run->target, run->rz, NULL, 0,
                                       inspect_after_face, &run->inspection, &run->err);
    return ok || fail(run);
}

bool run_write(Run *run)
{
    bool ok = render_write(&run->render, &run->target, run->rz, &run->opt, &run->err) &&
              (!run->after_write || run->after_write(run, &run->err));
    return ok || fail(run);
}

bool run_report(Run *run)
{
    render_print_summary(stdout, run->lesson->program, &run->render, &run->target, &run->opt);
    fputs(run->note, stdout);
    if (run->lesson->report)
        run->lesson->report(&run->target);
    run->status = inspect_report(stdout, &run->inspection, &run->target, &run->err);
    return run->status != EXIT_RUN_FAILED;
}

int run_end(Run *run)
{
    target_free(&run->target);
    render_free(&run->render);
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
