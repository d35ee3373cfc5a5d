/* The process-wide start object that every copy of the runtime in a process
 * shares (process_object.c), and its layout. */
#ifndef CARDAN_JOINT_PROCESS_OBJECT_H
#define CARDAN_JOINT_PROCESS_OBJECT_H

#include <pthread.h>
#include <stddef.h>

/* Layout 1: what every copy built from 546b100 on keeps in the object.  A change
 * to it is a new layout number; copies refuse a layout that is not theirs. */
struct process_python {
#ifdef CARDAN_JOINT_PROCESS_LAYOUT_TRIAL
    char moved[64]; /* tests only: a later layout that moved the lock */
#endif
    pthread_mutex_t lock;
    int state;          /* 0: not started by any copy; 1: running; -1: its start failed */
    char failure[2048]; /* why it failed, for every later instance */
    char in_use[1600];  /* for messages: which Python runs the slaves */
};
#ifdef CARDAN_JOINT_PROCESS_LAYOUT_TRIAL
#define PROCESS_LAYOUT 1000
#else
#define PROCESS_LAYOUT 1
#endif

/* The process's object once its layout is this copy's (the first copy to ask
 * claims it for its own), else NULL and why in error. */
struct process_python *process_object(char *error, size_t size);

#endif
