// SPDX-License-Identifier: GPL-3.0-or-later
#include "ConfigOption.h"

#include "project/Annotation.h"

namespace rs::ladder {

std::optional<ConfigOption> configOptionOf(const Network& network) {
    if (!network.record || network.items.size() != 1)
        return std::nullopt;
    std::optional<project::Annotation> record;
    try {
        record = project::parseAnnotation(network.record->text);
    } catch (const project::AnnotationError&) {
        return std::nullopt;
    }
    if (!record || record->kind != "network")
        return std::nullopt;
    const std::string state = record->value("option");
    if (state != "on" && state != "off")
        return std::nullopt;
    const auto* rung = std::get_if<Rung>(&network.items.front());
    if (!rung || rung->condition || rung->outputs.size() != 1)
        return std::nullopt;
    const Output& output = rung->outputs.front();
    const bool checked = state == "on";
    const auto wanted = checked ? lang::StatementKind::Set : lang::StatementKind::Reset;
    if (output.kind != wanted || output.target.address.kind != lang::AddressKind::Memory)
        return std::nullopt;
    return ConfigOption{network.comment, output.target, checked};
}

Network configOptionNetwork(const ConfigOption& option) {
    Network network;
    network.comment = option.description;
    network.record =
        lang::CommentLine{project::formatAnnotation({"network",
                                                     {},
                                                     {{"comment", option.description},
                                                      {"option", option.checked ? "on" : "off"}}}),
                          false};
    Output output;
    output.kind = option.checked ? lang::StatementKind::Set : lang::StatementKind::Reset;
    output.target = option.memory;
    network.items.push_back(Rung{std::nullopt, {output}});
    return network;
}

} // namespace rs::ladder
