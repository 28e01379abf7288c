/* Preloaded into sanitizer test runs only (scripts/test.sh, MATEVO_SANITIZE=1).
 *
 * The Vulkan loader unloads the driver (lavapipe) and the validation layer when the instance is
 * destroyed. Memory they still reference from their own globals then looks leaked to
 * LeakSanitizer, and what they really leak is reported from an "<unknown module>" that no
 * suppression can name. Opening both once more with RTLD_NODELETE keeps them mapped until exit;
 * RTLD_LOCAL keeps their symbols out of the global scope, so the loader still routes every call
 * through its own dispatch (preloading the layer itself would interpose its entry points). */
#include <dlfcn.h>

__attribute__((constructor)) static void pinVulkanModules(void) {
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    dlopen("libVkLayer_khronos_validation.so", RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
}
