// SPDX-License-Identifier: GPL-3.0-or-later
#include "NameCsv.h"

#include "ProgramText.h"
#include "lang/TextCase.h"
#include "project/VariableCsv.h"

#include <algorithm>
#include <cctype>

namespace rs::pl110 {

namespace {

std::string withoutSpaces(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return std::string(text);
}

// A name the text form reads back as a name: a letter (or any non-ASCII
// character) first, then letters, digits, '_' and '.'; not a keyword or an
// address.
std::string nameProblem(const std::string& name) {
    const auto first = static_cast<unsigned char>(name.front());
    const bool shaped =
        (std::isalpha(first) || first >= 0x80) && std::all_of(name.begin(), name.end(), [](char c) {
            const auto u = static_cast<unsigned char>(c);
            return std::isalnum(u) || u == '_' || u == '.' || u >= 0x80;
        });
    if (!shaped)
        return "'" + name + "' is not a name: a letter, then letters, digits, '_' or '.'";
    if (isKeyword(name))
        return "'" + name + "' is a keyword of the text form, not a name";
    if (readAddress(name).shape != AddressReading::Shape::NotAnAddress)
        return "'" + name + "' is an address, not a name";
    return {};
}

// Every operand of the rungs that spells `from` spells `to` (nothing: the address).
void respell(Program& program, const std::string& from, const std::string& to) {
    const auto operand = [&](Operand& o) {
        if (o.name == from)
            o.name = to;
    };
    const auto value = [&](Value& v) {
        if (v.operand)
            operand(*v.operand);
    };
    const auto circuit = [&](auto& self, Circuit& c) -> void {
        if (!c.isElement()) {
            for (Circuit& part : c.parts)
                self(self, part);
            return;
        }
        operand(c.element.operand);
        value(c.element.left);
        value(c.element.right);
    };
    for (auto* lines : {&program.init, &program.main})
        for (Line& line : *lines)
            if (auto* rung = std::get_if<Rung>(&line.body)) {
                if (rung->condition)
                    circuit(circuit, *rung->condition);
                operand(rung->output.target);
                value(rung->output.preset);
                value(rung->output.left);
                value(rung->output.right);
            }
}

// The declaration line of an address, or nothing.
Line* declarationOf(Program& program, const Address& address) {
    for (Line& line : program.declarations)
        if (const auto* declaration = std::get_if<NameDeclaration>(&line.body))
            if (declaration->variable.address == address)
                return &line;
    return nullptr;
}

} // namespace

std::optional<NamingProblem> nameAddress(Program& program, const Address& address,
                                         const std::string& name, const std::string& description,
                                         bool& changed) {
    changed = false;
    if (description.find_first_of("\r\n") != std::string::npos)
        return NamingProblem{2, "a description is one line"};
    Line* declaredLine = declarationOf(program, address);
    NameDeclaration* declared =
        declaredLine ? &std::get<NameDeclaration>(declaredLine->body) : nullptr;
    if (name.empty()) {
        if (!description.empty())
            return NamingProblem{
                1, "a description needs a name: the text form keeps it on the name's line"};
        if (declared) {
            respell(program, declared->name, {});
            program.declarations.erase(program.declarations.begin() +
                                       (declaredLine - program.declarations.data()));
            changed = true;
        }
        return std::nullopt;
    }
    if (std::string why = nameProblem(name); !why.empty())
        return NamingProblem{1, std::move(why)};
    // The same name on another address would make the text ambiguous.
    const bool taken = std::any_of(program.declarations.begin(), program.declarations.end(),
                                   [&](const Line& line) {
                                       const auto* d = std::get_if<NameDeclaration>(&line.body);
                                       return d && lang::toUpper(d->name) == lang::toUpper(name) &&
                                              !(d->variable.address == address);
                                   });
    if (taken)
        return NamingProblem{1, "'" + name + "' already names another address"};
    std::optional<std::string> comment;
    if (!description.empty())
        comment = " " + description;
    if (declared) {
        if (declared->name == name && declaredLine->comment == comment)
            return std::nullopt;
        respell(program, declared->name, name);
        declared->name = name;
        declaredLine->comment = comment;
    } else {
        Line line;
        NameDeclaration declaration;
        declaration.variable.address = address;
        declaration.name = name;
        line.body = declaration;
        line.comment = comment;
        program.declarations.push_back(std::move(line));
    }
    changed = true;
    return std::nullopt;
}

std::string exportNamesCsv(const Program& program, char separator) {
    const std::string sep(1, separator);
    std::string csv = "\xEF\xBB\xBFVariable" + sep + "Symbolic Name" + sep + "Description\r\n";
    for (const Line& line : program.declarations)
        if (const auto* declaration = std::get_if<NameDeclaration>(&line.body))
            csv += project::csvField(toString(declaration->variable.address), separator) + sep +
                   project::csvField(declaration->name, separator) + sep +
                   project::csvField(withoutSpaces(line.comment.value_or("")), separator) + "\r\n";
    return csv;
}

NameCsvImport importNamesCsv(const Program& program, std::string_view csv) {
    NameCsvImport result;
    result.program = program;
    std::vector<project::CsvRecord> records;
    try {
        records = project::readCsv(csv, project::detectCsvSeparator(csv));
    } catch (const project::CsvSyntaxError& error) {
        result.problems.push_back({error.line, error.column, error.message});
        return result;
    }
    for (const project::CsvRecord& record : records) {
        const auto fieldAt = [&](std::size_t i) {
            return i < record.fields.size() ? withoutSpaces(record.fields[i]) : std::string();
        };
        const auto columnAt = [&](std::size_t i) {
            return record.places[std::min(i, record.places.size() - 1)].column;
        };
        const auto problem = [&](std::size_t i, std::string message) {
            result.problems.push_back({record.places[std::min(i, record.places.size() - 1)].line,
                                       columnAt(i), std::move(message)});
        };
        const std::string variable = fieldAt(0);
        const std::string name = fieldAt(1);
        const std::string description = fieldAt(2);
        if (record.fields.size() == 1 && variable.empty())
            continue; // a blank line
        if (lang::toLower(variable) == "variable" || lang::toLower(variable) == "address")
            continue; // the heading row
        const AddressReading reading = readAddress(variable);
        if (reading.shape != AddressReading::Shape::Address) {
            problem(0, reading.shape == AddressReading::Shape::Malformed
                           ? reading.error
                           : "'" + variable + "' is not a PL110 address");
            continue;
        }
        bool changed = false;
        if (const auto why =
                nameAddress(result.program, reading.address, name, description, changed)) {
            problem(static_cast<std::size_t>(why->field), why->message);
            continue;
        }
        if (changed)
            ++result.changed;
    }
    return result;
}

} // namespace rs::pl110
