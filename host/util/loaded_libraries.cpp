#include "util/loaded_libraries.h"

#include <dlfcn.h>
#include <link.h>

namespace tsis {

void keepLoadedLibrariesMapped() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            if (info->dlpi_name && info->dlpi_name[0])
                dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD);
            return 0;
        },
        nullptr);
}

}  // namespace tsis
