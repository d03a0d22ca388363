/* Signals and the end of the process, for src/os/vibrobeam_signals.f90 and the program:
 * the SIGINT/SIGTERM handler (a handler must only set a volatile sig_atomic_t), SIGXFSZ
 * ignored, and an exit that skips atexit handlers. Every function returns 0 or an errno
 * value and never prints; the Fortran side turns that into a message. */
#define _GNU_SOURCE
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* ---------------------------------------------------------------------------------
 * Signals */

/* The signal that asked the run to stop (SIGINT, SIGTERM or SIGUSR1), 0 while none did.
 * SIGUSR1 is there for runs under OpenMPI's mpirun, which forwards it to every rank and
 * keeps their exit status, where SIGINT/SIGTERM to mpirun end the job with status 1
 * (docs/sweeps.md, "Parallel runs"). */
static volatile sig_atomic_t interrupt_signal = 0;

/* First SIGINT/SIGTERM/SIGUSR1: remember it and give them back their default action,
 * so a second one ends the process at once (async-signal-safe: sigaction only). */
static void on_interrupt(int signal_number)
{
    struct sigaction default_action;
    memset(&default_action, 0, sizeof default_action);
    default_action.sa_handler = SIG_DFL;
    sigemptyset(&default_action.sa_mask);
    interrupt_signal = signal_number;
    sigaction(SIGINT, &default_action, NULL);
    sigaction(SIGTERM, &default_action, NULL);
    sigaction(SIGUSR1, &default_action, NULL);
}

int vb_install_interrupt_handlers(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_interrupt;
    sigemptyset(&action.sa_mask);
    /* SA_RESTART: a system call interrupted by the first signal resumes (an fsync or a
     * write in progress completes), the loop then sees the flag. */
    action.sa_flags = SA_RESTART;
    if (sigaction(SIGINT, &action, NULL) != 0) return errno;
    if (sigaction(SIGTERM, &action, NULL) != 0) return errno;
    if (sigaction(SIGUSR1, &action, NULL) != 0) return errno;
    return 0;
}

int vb_interrupt_signal(void) { return (int)interrupt_signal; }

/* SIGXFSZ (a write beyond `ulimit -f`) kills the process by default, and libgfortran
 * installs a backtrace handler for it; ignored, the write fails with EFBIG instead and
 * is reported like any other I/O error. */
int vb_ignore_file_size_signal(void)
{
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = SIG_IGN;
    sigemptyset(&action.sa_mask);
    if (sigaction(SIGXFSZ, &action, NULL) != 0) return errno;
    return 0;
}

/* End the process with `status` at once: stdio flushed, no atexit handlers. HDF5's own
 * exit handler would try again to write a file whose every write fails (a full disk)
 * and can crash doing so; by then every result file has been closed or discarded. */
void vb_exit(int status)
{
    fflush(NULL);
    _exit(status);
}
