/* Each part of the public header stands on its own as strict C11: a
 * customer may include proxima/devices.h, proxima/threads.h or
 * proxima/inspect.h first and gets the whole API, as from proxima/proxima.h. */
#include <proxima/devices.h>
#include <proxima/threads.h>
#include <proxima/inspect.h>

int main(void) {
  /* A function of each part, from a header included through another. */
  proxThreadsDef threads = proxDefaultThreadsDef();
  proxStreamDeviceDef stream = proxDefaultStreamDeviceDef();
  (void)stream;
  proxForceSettings force;
  double cutoff = 0.0;
  const int ok = proxGetForcePreset(PROX_FORCE_PRESET_HARD, &force, &cutoff) == PROX_SUCCESS && cutoff > 0.0 &&
                 threads.hapticRate > 0.0 && proxWorld_IsValid((proxWorldId){0}) == 0;
  return ok ? 0 : 1;
}
