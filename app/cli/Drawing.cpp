// SPDX-License-Identifier: GPL-3.0-or-later
#include "Drawing.h"

#include "RungsmithBuildVersion.h"

#include <dlfcn.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace rs::cli {

namespace {

const DrawingModule* loadedModule = nullptr;

// Beside the program in the build tree; in libexec/rungsmith beside bin/ where
// installed. Never from elsewhere: a module of another build would take this
// program's core for its own.
std::vector<std::filesystem::path> modulePlaces() {
    std::error_code error;
    const std::filesystem::path program = std::filesystem::canonical("/proc/self/exe", error);
    if (error)
        return {};
    const std::filesystem::path dir = program.parent_path();
    return {dir / "rungsmith-drawing.so", dir / "../libexec/rungsmith/rungsmith-drawing.so"};
}

const DrawingModule* loadModule() {
    std::string reasons;
    for (const std::filesystem::path& place : modulePlaces()) {
        if (!std::filesystem::exists(place))
            continue;
        void* handle = dlopen(place.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            reasons += std::string("\n  ") + dlerror();
            continue;
        }
        const auto entry = reinterpret_cast<DrawingModuleEntry>(dlsym(handle, kDrawingModuleEntry));
        const DrawingModule* module = entry ? entry() : nullptr;
        if (module && !std::strcmp(module->build, RUNGSMITH_BUILD_VERSION))
            return module; // stays loaded: the application it makes lives until the end
        reasons += "\n  " + place.string() + " is from another build (" +
                   (module ? module->build : "no entry") + ")";
        dlclose(handle);
    }
    std::fprintf(stderr,
                 "rungsmith-cli: drawing needs rungsmith-drawing.so of rungsmith-cli %s beside "
                 "the program or in ../libexec/rungsmith%s\n",
                 RUNGSMITH_BUILD_VERSION, reasons.empty() ? "; there is none" : reasons.c_str());
    return nullptr;
}

} // namespace

std::unique_ptr<QCoreApplication> makeApplication(int& argc, char** argv) {
    const bool draws = std::any_of(argv + 1, argv + argc, [](const char* argument) {
        return !std::strcmp(argument, "ladder") || !std::strncmp(argument, "--pdf", 5);
    });
    if (!draws)
        return std::make_unique<QCoreApplication>(argc, argv);
    loadedModule = loadModule();
    return loadedModule ? loadedModule->makeApplication(argc, argv) : nullptr;
}

const DrawingModule& drawing() {
    if (!loadedModule) // a verb that draws, not named to makeApplication: a bug, said as one
        throw std::logic_error("the drawing module was not loaded for this verb");
    return *loadedModule;
}

} // namespace rs::cli
