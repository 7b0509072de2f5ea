/*
 * src/base/module.h - opening libqdot's optional modules (qdot-modules/
 * qdot_NAME.so) at run time, so that a heavy dependency (OpenMPI, HDF5)
 * is loaded only by the call that uses it (src/sweep/ext.h says why).
 *
 * The module is looked for, in this order, in
 *   1. $QDOT_MODULE_DIR, when set (tests, relocated installs);
 *   2. qdot-modules/ beside the object that holds libqdot: libqdot.so, or
 *      the program that links its archive (the build tree's ./qdot);
 *   3. qdot-modules/ beside the running program (/proc/self/exe);
 *   4. ../<libdir>/qdot-modules from the running program (a tree installed
 *      under another prefix than it was configured for);
 *   5. QDOT_MODULE_INSTALL_DIR, fixed when libqdot was built
 *      (${libdir}/qdot-modules: an installed /usr/local/bin/qdot).
 * A module is opened once and never closed (MPI cannot be unloaded and
 * started again); dlopen's own reference count makes repeated opens cheap
 * and thread-safe.
 */
#ifndef QD_BASE_MODULE_H
#define QD_BASE_MODULE_H

#include <stdbool.h>
#include <stddef.h>
#include "qdot/expr.h"

/* The module qdot_NAME.so with flags for dlopen (RTLD_GLOBAL for one whose
 * dependencies load plug-ins of their own, as OpenMPI does), checked to
 * export `unsigned qd_ext_NAME_abi(void)` returning abi.  NULL when it is
 * missing, fails to load or is of another ABI: QD_ERR_UNSUPPORTED in ctx,
 * saying which, with `what` (the capability, "MPI") and `pkg` (the Debian
 * package to build it with) in the message. */
void *qd__module_open(qd_ctx *ctx, const char *name, int flags, unsigned abi, const char *what,
                      const char *pkg);

/* The function sym of an opened module (name for the message) into *fn,
 * a function pointer of fnsize bytes: ISO C has no cast from dlsym's
 * object pointer, so it is copied.  False (QD_ERR_UNSUPPORTED in ctx)
 * when absent. */
bool qd__module_fn(qd_ctx *ctx, void *module, const char *name, const char *sym, void *fn,
                   size_t fnsize);

#endif
