#include "util/embedded.h"

#include "util/error.h"

namespace tsis {

std::string_view embeddedText(const std::vector<EmbeddedFile>& files, std::string_view name) {
    for (const EmbeddedFile& f : files)
        if (name == f.name) return f.text;
    checkFailed(__FILE__, __LINE__, concat("no embedded file named '", name, "'"));
}

}  // namespace tsis
