/* One BLAS thread per sweep task (docs/sweeps.md, "Parallel runs"): a sweep runs its
 * tasks on all cores itself, and a threaded BLAS inside each task would oversubscribe the
 * cores and make a result depend on how its sums were split. The program links the
 * generic libblas.so.3, so which library runs is chosen at load time: the thread-count
 * setters of OpenBLAS (and of its GotoBLAS ancestry) are looked up at run time and called
 * when present; the reference BLAS has none and is single-threaded anyway. Returns the
 * number of setters called (0: none present). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stddef.h>

int vb_blas_single_thread(void)
{
    static const char *const setters[] = {"openblas_set_num_threads", "goto_set_num_threads"};
    int called = 0;
    for (unsigned k = 0; k < sizeof setters / sizeof setters[0]; ++k) {
        void (*set_threads)(int) = (void (*)(int))dlsym(RTLD_DEFAULT, setters[k]);
        if (set_threads != NULL) {
            set_threads(1);
            ++called;
        }
    }
    return called;
}
