/* Bind the runtime to glibc 2.17's symbol versions (the manylinux2014 floor), so
 * that the FMU built on a new glibc loads where FMI tools run (glibc 2.17-2.33).
 * Given to every source by the build (-include), never #included by hand.
 *
 * glibc 2.34 moved libdl and libpthread into libc.so.6 and gave their functions
 * a new default version, GLIBC_2.34, which an older glibc lacks ("version
 * 'GLIBC_2.34' not found").  libc.so.6 keeps the old versions as compatibility
 * symbols: .symver binds a reference to one.  An older glibc has no dlopen in
 * libc.so.6 at all, but symbol lookup matches a version by name in every library
 * of the FMU's scope: the build links libdl.so.2 and libpthread.so.0 as needed
 * libraries, so there the same reference finds libdl's dlopen@@GLIBC_2.2.5.
 *
 * An unreferenced .symver emits nothing.  The versions are x86_64's oldest ones;
 * tests/fmu/test_symbol_versions.py fails for any reference above 2.17.
 */
#ifndef CARDAN_JOINT_GLIBC_COMPAT_H
#define CARDAN_JOINT_GLIBC_COMPAT_H

#if defined(__x86_64__) && defined(__linux__) && !defined(__ASSEMBLER__)

#define CARDAN_JOINT_BIND(name, old) __asm__(".symver " #name "," #old);
#define CARDAN_JOINT_OLD_VERSION(name, version) CARDAN_JOINT_BIND(name, name@version)

/* libdl (glibc 2.34: GLIBC_2.34) */
CARDAN_JOINT_OLD_VERSION(dlopen, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dlsym, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dlvsym, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dlclose, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dlerror, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dladdr, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(dladdr1, GLIBC_2.3.3)
CARDAN_JOINT_OLD_VERSION(dlinfo, GLIBC_2.3.3)

/* libpthread (glibc 2.34: GLIBC_2.34) */
CARDAN_JOINT_OLD_VERSION(pthread_create, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_join, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_detach, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_once, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_key_create, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_key_delete, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_getspecific, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_setspecific, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_mutex_trylock, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_mutexattr_init, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_mutexattr_destroy, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_mutexattr_settype, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_rwlock_init, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_rwlock_destroy, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_rwlock_rdlock, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_rwlock_wrlock, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_rwlock_unlock, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pthread_attr_setstacksize, GLIBC_2.2.5)

/* libm (glibc 2.29: GLIBC_2.29, the generated step's exp, log and pow): 2.29
 * dropped the SVID error wrappers from the default versions; the old versions
 * wrap the same functions and differ only in errno and in how an overflow or a
 * domain error is reported, which the generated step guards before it calls.
 * exp and log, which life calls at every node (x^p = exp(p log x)), bind to
 * __exp_finite and __log_finite (GLIBC_2.15): the same functions without the
 * wrapper, which cost 17 instructions a call (about 1.4 k of a joint's
 * step at 1000 rad/s, callgrind); glibc 2.31 keeps them as
 * compatibility aliases of exp and log, so every glibc gives the same bits. */
CARDAN_JOINT_BIND(exp, __exp_finite@GLIBC_2.15)
CARDAN_JOINT_OLD_VERSION(exp2, GLIBC_2.2.5)
CARDAN_JOINT_BIND(log, __log_finite@GLIBC_2.15)
CARDAN_JOINT_OLD_VERSION(log2, GLIBC_2.2.5)
CARDAN_JOINT_OLD_VERSION(pow, GLIBC_2.2.5)

/* fcntl: glibc 2.28's headers may redirect it to fcntl64 (GLIBC_2.28); the
 * same function on x86_64.  stat, fstat and lstat (GLIBC_2.33) have no older
 * version of the same name: the runtime uses access() and fopen() instead. */
CARDAN_JOINT_BIND(fcntl64, fcntl@GLIBC_2.2.5)

#undef CARDAN_JOINT_OLD_VERSION
#undef CARDAN_JOINT_BIND
#endif
#endif
