/* proxima/base.h and proxima/types.h stand on their own as strict C11, and
 * bring only what they are for: a program that holds ids and defs (an
 * engine's component header) includes proxima/types.h without the
 * functions of proxima/proxima.h. */
#include <proxima/types.h>

#ifdef PROXIMA_PROXIMA_H
#error "proxima/types.h includes proxima/proxima.h"
#endif
#ifndef PROXIMA_BASE_H
#error "proxima/types.h does not include proxima/base.h"
#endif

int main(void) {
  /* base.h: the version, results and errors; types.h: the defs' defaults. */
  const proxVersion v = proxGetVersion();
  const proxWorldDef world = proxDefaultWorldDef();
  const proxBodyDef body = proxDefaultBodyDef();
  const proxMeshId none = {0, 0, {0, 0}};
  const int ok = v.major == PROX_VERSION_MAJOR && world.apiVersion == PROX_API_VERSION &&
                 body.type == PROX_BODY_STATIC && none.index1 == 0 && proxResultString(PROX_SUCCESS)[0] == 'P' &&
                 proxGetLastError() != NULL;
  return ok ? 0 : 1;
}
