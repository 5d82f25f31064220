// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockInstance.h"

#include "BlockLibrary.h"
#include "BodyTemplate.h"
#include "project/Annotation.h"
#include "project/Utf8Text.h"

#include <variant>

namespace rs::blocks {

namespace {

const Binding* findBinding(const std::vector<Binding>& bindings, std::string_view name) {
    for (const auto& binding : bindings)
        if (sameName(binding.name, name))
            return &binding;
    return nullptr;
}

} // namespace

const Binding* BlockInstance::findPin(std::string_view pin) const {
    return findBinding(pins, pin);
}

const Binding* BlockInstance::findPrivate(std::string_view name) const {
    return findBinding(privates, name);
}

std::optional<BlockInstance> instanceOf(const project::Annotation& record, std::string_view text,
                                        lang::SourceLocation at, lang::Diagnostics& diagnostics) {
    if (record.kind != kBlockRecord)
        return std::nullopt;
    auto error = [&](std::string message, int column = 0) {
        diagnostics.push_back(
            {lang::Severity::Error, at.line, column ? column : at.column, std::move(message)});
    };
    // The column of each key in turn: keys stand in the text in their order.
    std::size_t searched = 0;
    auto columnOf = [&](const std::string& key) {
        const std::size_t found = text.find(" " + key + "=", searched);
        if (found == std::string_view::npos)
            return 0;
        searched = found + key.size() + 2;
        return at.column + project::characterColumn(text, found + 1);
    };
    if (record.arguments.size() != 1) {
        error(record.arguments.empty()
                  ? "@block needs the block's name, as in ;@block ResetLatch Enable=\"I0.0\""
                  : "@block takes one block name; pins are written PIN=\"OPERAND\"");
        return std::nullopt;
    }
    BlockInstance instance;
    instance.type = record.arguments.front();
    instance.location = at;
    bool good = true;
    for (const auto& [key, value] : record.attributes) {
        const int column = columnOf(key);
        if (key == "lib") {
            instance.library = value;
        } else if (key == "version") {
            instance.version = value;
        } else if (!key.empty() && key.front() == '#') {
            const std::string name = key.substr(1);
            if (name.empty() || instance.findPrivate(name)) {
                error("@block " + instance.type + ": private variable '" + key +
                          (name.empty() ? "' has no name" : "' is given twice"),
                      column);
                good = false;
                continue;
            }
            instance.privates.push_back({name, value, column});
        } else {
            if (instance.findPin(key)) {
                error("@block " + instance.type + ": pin '" + key + "' is bound twice", column);
                good = false;
                continue;
            }
            instance.pins.push_back({key, value, column});
        }
    }
    if (!good)
        return std::nullopt;
    return instance;
}

std::string recordText(const BlockInstance& instance) {
    project::Annotation record;
    record.kind = kBlockRecord;
    record.arguments.push_back(instance.type);
    for (const auto& pin : instance.pins)
        record.attributes.emplace_back(pin.name, pin.operand);
    if (!instance.library.empty())
        record.attributes.emplace_back("lib", instance.library);
    if (!instance.version.empty())
        record.attributes.emplace_back("version", instance.version);
    for (const auto& variable : instance.privates)
        record.attributes.emplace_back("#" + variable.name, variable.operand);
    return project::formatAnnotation(record);
}

StepInstances findInstances(const lang::Step& step) {
    StepInstances found;
    auto error = [&](lang::SourceLocation at, std::string message) {
        found.diagnostics.push_back(
            {lang::Severity::Error, at.line, at.column, std::move(message)});
    };
    std::optional<BlockInstance> open;
    for (std::size_t i = 0; i < step.lines.size(); ++i) {
        const lang::Line& line = step.lines[i];
        const auto record = project::annotationOn(line);
        if (!record)
            continue;
        if (record->kind == kEndRecord) {
            if (!open) {
                error(line.location, "@end without a ;@block before it");
                continue;
            }
            open->end = i;
            found.instances.push_back(std::move(*open));
            open.reset();
        } else if (record->kind == kBlockRecord) {
            if (open) {
                error(open->location, "@block " + open->type +
                                          " has no ;@end before the next ;@block; an instance "
                                          "cannot hold another");
                open.reset();
            }
            open = instanceOf(*record, std::get<lang::CommentLine>(line.body).text, line.location,
                              found.diagnostics);
            if (open)
                open->record = i;
        } else if (open && record->kind == "network") {
            error(line.location,
                  "@network inside the instance of " + open->type + "; close it with ;@end first");
        }
    }
    if (open)
        error(open->location, "@block " + open->type + " has no ;@end before the step ends");
    return found;
}

} // namespace rs::blocks
