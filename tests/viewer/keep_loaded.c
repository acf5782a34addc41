/* Preloaded into proxima-viewer by its tests under AddressSanitizer only
 * (tests/viewer/sanitizers.py): a dlclose that keeps every library loaded.
 * The Vulkan loader unloads the driver and the validation layer when the
 * instance is destroyed, before LeakSanitizer's check at exit; kept loaded,
 * their allocations are named by module, and lsan.supp can suppress those
 * and nothing else. */
int dlclose(void* handle);

int dlclose(void* handle) {
  (void)handle;
  return 0;
}
