// The methods `--method` can name (docs/design.md §4). Add a method here.
#include "render/method.h"
#include "render/method_hierarchical.h"
#include "render/method_hybrid.h"
#include "render/method_lss.h"
#include "render/method_ltsm.h"
#include "render/method_mis.h"
#include "render/method_pyramid.h"
#include "render/method_reference.h"
#include "render/method_tsis.h"
#include "render/method_tsm.h"
#include "render/method_volumetric.h"
#include "util/error.h"

namespace tsis {

namespace {

struct Entry {
    const char* name;
    std::unique_ptr<Method> (*make)(ClRuntime& cl);
};

const Entry kMethods[] = {
    {"pyramid",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<PyramidMethod>(cl); }},
    {"tsis",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<TsisMethod>(cl); }},
    {"hybrid",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<HybridMethod>(cl); }},
    {"ltsm",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<LtsmMethod>(cl); }},
    {"mis",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<MisMethod>(cl); }},
    {"hierarchical",
     [](ClRuntime& cl) -> std::unique_ptr<Method> {
         return std::make_unique<HierarchicalMethod>(cl);
     }},
    {"reference",
     [](ClRuntime& cl) -> std::unique_ptr<Method> {
         return std::make_unique<ReferenceMethod>(cl);
     }},
    {"tsm",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<TsmMethod>(cl); }},
    {"lss",
     [](ClRuntime& cl) -> std::unique_ptr<Method> { return std::make_unique<LssMethod>(cl); }},
    {"volumetric",
     [](ClRuntime& cl) -> std::unique_ptr<Method> {
         return std::make_unique<VolumetricMethod>(cl);
     }},
};

}  // namespace

std::unique_ptr<Method> makeMethod(const std::string& name, ClRuntime& cl) {
    for (const Entry& e : kMethods)
        if (name == e.name) return e.make(cl);
    std::string list;
    for (const Entry& e : kMethods) list += (list.empty() ? "" : ", ") + std::string(e.name);
    fail("unknown method '", name, "'; available: ", list);
}

std::vector<std::string> methodNames() {
    std::vector<std::string> names;
    for (const Entry& e : kMethods) names.push_back(e.name);
    return names;
}

}  // namespace tsis
