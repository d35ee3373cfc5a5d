/* The process's one start of Python, shared by every copy of the runtime.
 *
 * Every copy in a process (several FMUs, FMI 2.0 and 3.0, each its own .so
 * loaded RTLD_LOCAL, first instantiated from threads at the same moment) must
 * agree on one start.  Separate copies share no statics, so the lock and the
 * outcome live in one object the dynamic linker unifies: a symbol of binding
 * STB_GNU_UNIQUE (the mechanism that gives C++ inline statics one instance
 * across RTLD_LOCAL libraries) resolves, in every copy that references it
 * through its GOT, to the first loaded definition.  (flock would need a file;
 * scanning loaded objects with dl_iterate_phdr races with a concurrent dlopen.)
 *
 * Copies from other releases may share it, so it says its own layout: the
 * object's last 64 bytes hold one word, (layout << 32) | size of the layout's
 * struct, which the first copy to ask sets with a compare-and-swap, before any
 * lock is taken.  A copy that finds another layout there refuses with both
 * named and never touches the lock it cannot find.  The copies of 546b100 to
 * this change set no word; their layout is layout 1, which is why the word
 * lives where layout 1 leaves the object zero.  Every later layout keeps the
 * object's name, its size and the word's place, and changes its number.
 */
#define _GNU_SOURCE
#include "process_object.h"

#include <stdio.h>

#define PROCESS_PYTHON "cardan_joint_fmu_process_python_v1"
#define PROCESS_PYTHON_SIZE 4096
#define LAYOUT_WORD (PROCESS_PYTHON_SIZE - 64)
__asm__(".globl " PROCESS_PYTHON "\n"
        ".pushsection .bss." PROCESS_PYTHON ",\"aw\",@nobits\n"
        ".balign 64\n"
        ".type " PROCESS_PYTHON ", @gnu_unique_object\n"
        ".size " PROCESS_PYTHON ", 4096\n" PROCESS_PYTHON ":\n"
        ".zero 4096\n"
        ".popsection\n");
extern char cardan_joint_fmu_process_python_v1[PROCESS_PYTHON_SIZE];
_Static_assert(sizeof(struct process_python) <= LAYOUT_WORD, "the layout word's place");
/* All zero bytes are an unlocked mutex (glibc's PTHREAD_MUTEX_INITIALIZER) and state 0. */

struct process_python *process_object(char *error, size_t size)
{
    char *object = cardan_joint_fmu_process_python_v1;
    unsigned long long *word = (unsigned long long *)(object + LAYOUT_WORD);
    unsigned long long mine = (unsigned long long)PROCESS_LAYOUT << 32 |
                              sizeof(struct process_python), found = 0;
    if (__atomic_compare_exchange_n(word, &found, mine, 0, __ATOMIC_ACQ_REL, __ATOMIC_ACQUIRE) ||
        found == mine)
        return (struct process_python *)object;
    snprintf(error, size, "another FMU in this process, built by another release of this "
             "project, keeps the process's Python start in layout %llu (%llu bytes); this "
             "FMU's runtime knows layout %d (%zu bytes) only and cannot share it: run FMUs "
             "built by one release in one process", found >> 32, found & 0xffffffffULL,
             PROCESS_LAYOUT, sizeof(struct process_python));
    return NULL;
}
