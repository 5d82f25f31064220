// SPDX-License-Identifier: GPL-3.0-or-later
#include "VariableCsv.h"

#include "UnitSettings.h"
#include "Utf8Text.h"
#include "VariableTable.h"
#include "lang/SymbolicName.h"
#include "lang/TextCase.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

namespace rs::project {

namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
const std::vector<std::string> kHeadings{"Variable", "Symbolic Name", "Description"};

std::string_view withoutByteOrderMark(std::string_view csv) {
    if (csv.starts_with(kByteOrderMark))
        csv.remove_prefix(kByteOrderMark.size());
    return csv;
}

std::string trimmed(std::string_view text) {
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t'))
        text.remove_prefix(1);
    while (!text.empty() && (text.back() == ' ' || text.back() == '\t'))
        text.remove_suffix(1);
    return std::string(text);
}

// Which field holds what: from the heading row when there is one, else
// variable, name, description in that order.
struct Columns {
    int variable = 0;
    int name = 1;
    int description = 2;
};

std::optional<Columns> headingColumns(const CsvRecord& record) {
    Columns columns{-1, -1, -1};
    for (int i = 0; i < static_cast<int>(record.fields.size()); ++i) {
        const std::string heading =
            lang::toLower(trimmed(record.fields[static_cast<std::size_t>(i)]));
        if (heading == "variable" || heading == "address")
            columns.variable = i;
        else if (heading == "symbolic name" || heading == "name")
            columns.name = i;
        else if (heading == "description")
            columns.description = i;
    }
    if (columns.variable < 0)
        return std::nullopt;
    return columns;
}

std::string field(const CsvRecord& record, int column) {
    if (column < 0 || column >= static_cast<int>(record.fields.size()))
        return {};
    return record.fields[static_cast<std::size_t>(column)];
}

// Where a field starts; where the row's last field starts when it has not that many.
CsvPlace placeOf(const CsvRecord& record, int column) {
    if (column < 0 || column >= static_cast<int>(record.places.size()))
        return record.places.back();
    return record.places[static_cast<std::size_t>(column)];
}

// Walks a text byte by byte, knowing the line and column it is at.
class TextCursor {
public:
    explicit TextCursor(std::string_view text) : m_text(text) {}

    bool atEnd() const { return m_pos >= m_text.size(); }
    char peek() const { return m_text[m_pos]; }
    std::size_t offset() const { return m_pos; }
    CsvPlace place() const { return {m_line, m_column}; }
    char take() {
        const char c = m_text[m_pos++];
        if (c == '\n' || (c == '\r' && (atEnd() || peek() != '\n'))) {
            ++m_line;
            m_column = 1;
        } else if (c != '\r' && !isUtf8Continuation(c)) {
            ++m_column;
        }
        return c;
    }

private:
    std::string_view m_text;
    std::size_t m_pos = 0;
    int m_line = 1;
    int m_column = 1;
};

// Refuses what must never reach the project text.
void checkText(std::string_view csv) {
    const auto fault = findTextFault(csv);
    if (!fault)
        return;
    TextCursor cursor(csv);
    while (cursor.offset() < fault->offset)
        cursor.take();
    throw CsvSyntaxError{cursor.place().line, cursor.place().column, fault->message};
}

// One record at a time: the import holds no more than one row besides the text.
class CsvReader {
public:
    CsvReader(std::string_view csv, char separator)
        : m_cursor(withoutByteOrderMark(csv)), m_separator(separator) {}

    bool next(CsvRecord& record);

private:
    TextCursor m_cursor;
    char m_separator;
};

bool CsvReader::next(CsvRecord& record) {
    if (m_cursor.atEnd())
        return false;
    record = {m_cursor.place().line, {}, {}};
    while (true) {
        if (record.fields.size() == kCsvMaxFields)
            throw CsvSyntaxError{m_cursor.place().line, m_cursor.place().column,
                                 "a row has more than " + std::to_string(kCsvMaxFields) +
                                     " fields"};
        record.places.push_back(m_cursor.place());
        std::string current;
        if (!m_cursor.atEnd() && m_cursor.peek() == '"') {
            const CsvPlace opened = m_cursor.place();
            m_cursor.take();
            while (true) {
                if (m_cursor.atEnd())
                    throw CsvSyntaxError{opened.line, opened.column,
                                         "a quoted field is never closed"};
                const char c = m_cursor.take();
                if (c == '"') {
                    if (m_cursor.atEnd() || m_cursor.peek() != '"')
                        break;
                    m_cursor.take();
                }
                current += c;
            }
        }
        // Unquoted text, or what follows a closing quote up to the separator.
        while (!m_cursor.atEnd() && m_cursor.peek() != m_separator && m_cursor.peek() != '\n' &&
               m_cursor.peek() != '\r')
            current += m_cursor.take();
        record.fields.push_back(std::move(current));
        if (m_cursor.atEnd())
            return true;
        const char end = m_cursor.take();
        if (end == m_separator)
            continue;
        if (end == '\r' && !m_cursor.atEnd() && m_cursor.peek() == '\n')
            m_cursor.take();
        return true;
    }
}

bool blankRecord(const CsvRecord& record) {
    return std::all_of(record.fields.begin(), record.fields.end(),
                       [](const std::string& f) { return trimmed(f).empty(); });
}

} // namespace

std::string exportVariablesCsv(const Project& project, const CsvExportOptions& options) {
    struct Row {
        lang::Address address;
        std::string name;
        std::string description;
    };
    std::vector<Row> rows;
    for (const auto& unit : unitsOf(project)) {
        if (options.station && *options.station != unit.station)
            continue;
        const target::UnitTypeInfo& type = target::unitTypeInfo(unit.type);
        std::set<lang::Address> addresses;
        for (const auto& address : namedAddresses(project, unit.station))
            addresses.insert(address);
        for (const auto& [address, description] : project.variableDescriptions)
            if (address.unit == unit.station)
                addresses.insert(address);
        for (const auto& address : addresses) {
            const bool global = target::isGlobal(type, address);
            if ((options.scope == CsvScope::Global && !global) ||
                (options.scope == CsvScope::Local && global))
                continue;
            Row row{address, variableName(project, address), {}};
            if (auto it = project.variableDescriptions.find(address);
                it != project.variableDescriptions.end())
                row.description = it->second;
            if (!row.name.empty())
                row.name = options.prefix + row.name;
            rows.push_back(std::move(row));
        }
    }
    if (options.order == CsvOrder::ByName)
        std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) {
            // Rows without a name come last, in address order.
            return std::make_tuple(a.name.empty(), lang::foldName(a.name), a.address) <
                   std::make_tuple(b.name.empty(), lang::foldName(b.name), b.address);
        });

    const std::string separator(1, options.separator);
    auto line = [&](const std::vector<std::string>& fields) {
        std::string text;
        for (std::size_t i = 0; i < fields.size(); ++i) {
            if (i)
                text += separator;
            text += csvField(fields[i], options.separator);
        }
        return text + "\r\n";
    };
    std::string csv(kByteOrderMark);
    csv += line(kHeadings);
    for (const auto& row : rows)
        csv += line({lang::toString(row.address), row.name, row.description});
    return csv;
}

std::string csvField(const std::string& field, char separator) {
    const bool needsQuotes =
        field.find_first_of(std::string{separator, '"', '\r', '\n'}) != std::string::npos ||
        (!field.empty() && (field.front() == ' ' || field.back() == ' '));
    if (!needsQuotes)
        return field;
    std::string text = "\"";
    for (char c : field) {
        if (c == '"')
            text += '"';
        text += c;
    }
    return text + "\"";
}

char detectCsvSeparator(std::string_view csv) {
    csv = withoutByteOrderMark(csv);
    std::map<char, int> counts;
    bool inQuotes = false;
    for (char c : csv) {
        if (c == '"')
            inQuotes = !inQuotes;
        else if (!inQuotes && (c == '\n' || c == '\r'))
            break;
        else if (!inQuotes && (c == ';' || c == ',' || c == '\t'))
            ++counts[c];
    }
    char best = ',';
    int most = 0;
    for (char candidate : {',', ';', '\t'})
        if (counts[candidate] > most) {
            best = candidate;
            most = counts[candidate];
        }
    return best;
}

std::vector<CsvRecord> readCsv(std::string_view csv, char separator) {
    checkText(withoutByteOrderMark(csv));
    std::vector<CsvRecord> records;
    CsvReader reader(csv, separator);
    CsvRecord record;
    while (reader.next(record))
        records.push_back(std::move(record));
    return records;
}

CsvImport importVariablesCsv(const Project& project, std::string_view csv,
                             const CsvImportOptions& options) {
    CsvImport result;
    result.project = project;
    result.separator = detectCsvSeparator(csv);

    // Rows that can be read, before names are checked against each other.
    struct Candidate {
        int line;
        CsvPlace namePlace;
        lang::Address address;
        std::string name;
        std::string description;
    };
    std::vector<Candidate> candidates;
    std::map<lang::Address, int> seen;
    int unlisted = 0;
    CsvPlace firstUnlisted;
    auto problem = [&](const CsvPlace& place, std::string message) {
        if (result.problems.size() < kCsvListedProblems) {
            result.problems.push_back({place.line, place.column, std::move(message)});
        } else if (unlisted++ == 0) {
            firstUnlisted = place;
        }
    };
    try {
        checkText(withoutByteOrderMark(csv));
        CsvReader reader(csv, result.separator);
        CsvRecord record;
        std::optional<Columns> columns;
        while (reader.next(record)) {
            if (blankRecord(record))
                continue;
            if (!columns) {
                columns = headingColumns(record);
                if (columns && columns->name < 0) {
                    problem({record.line, 1}, "the heading row has no \"Symbolic Name\" column");
                    return result;
                }
                if (columns)
                    continue;
                columns = Columns{};
            }
            const CsvPlace variablePlace = placeOf(record, columns->variable);
            const std::string word = trimmed(field(record, columns->variable));
            const lang::AddressWord read = lang::readAddressWord(word);
            // A sequence's step number is addressed like a variable but takes no name.
            if (read.shape != lang::AddressWord::Shape::Variable ||
                read.address.kind == lang::AddressKind::Sequence) {
                problem(variablePlace, "'" + word + "' is not a variable such as I0.0 or M1.12");
                continue;
            }
            const lang::Address& address = read.address;
            if (options.station && address.unit != *options.station) {
                problem(variablePlace, lang::toString(address) + " belongs to unit " +
                                           std::to_string(address.unit) + ", not to unit " +
                                           std::to_string(*options.station));
                continue;
            }
            const auto unit = unitSettings(project, address.unit);
            if (!unit) {
                problem(variablePlace, "the project has no unit " + std::to_string(address.unit));
                continue;
            }
            const target::UnitTypeInfo& type = target::unitTypeInfo(unit->type);
            if (!target::hasVariable(type, address, unit->instructionSet)) {
                problem(variablePlace,
                        std::string(type.display) + " units have no " + lang::toString(address));
                continue;
            }
            if (auto it = seen.find(address); it != seen.end()) {
                problem(variablePlace, lang::toString(address) + " is already in line " +
                                           std::to_string(it->second));
                continue;
            }
            seen.emplace(address, record.line);
            std::string name = trimmed(field(record, columns->name));
            if (!options.prefix.empty() && name.starts_with(options.prefix))
                name.erase(0, options.prefix.size());
            candidates.push_back({record.line, placeOf(record, columns->name), address,
                                  std::move(name), field(record, columns->description)});
        }
    } catch (const CsvSyntaxError& error) {
        result.problems = {{error.line, error.column, error.message}};
        return result;
    }
    if (unlisted > 0)
        result.problems.push_back({firstUnlisted.line, firstUnlisted.column,
                                   std::to_string(unlisted) + " more bad rows, not listed"});

    // Every variable whose name changes first gets a stand-in name, so that
    // two variables can swap names; declarations are renamed in place, which
    // keeps their comments.
    Project& imported = result.project;
    std::map<lang::Address, std::string> oldNames;
    int standIns = 0;
    for (const auto& candidate : candidates) {
        const std::string oldName = variableName(project, candidate.address);
        oldNames[candidate.address] = oldName;
        if (oldName.empty() || oldName == candidate.name)
            continue;
        std::string standIn;
        do
            standIn = "CsvImport" + std::to_string(++standIns);
        while (checkVariableName(imported, candidate.address, standIn));
        setVariableName(imported, candidate.address, standIn);
    }
    for (const auto& candidate : candidates) {
        const std::string& oldName = oldNames[candidate.address];
        if (auto refused = setVariableName(imported, candidate.address, candidate.name)) {
            std::string message = *refused;
            if (setVariableName(imported, candidate.address, oldName))
                message += "; its old name '" + oldName + "' is taken now, so it has none";
            result.problems.push_back(
                {candidate.namePlace.line, candidate.namePlace.column, std::move(message)});
            if (!oldName.empty() && !(variableName(imported, candidate.address) == oldName))
                setVariableName(imported, candidate.address, {});
            continue;
        }
        std::string oldDescription;
        if (auto it = project.variableDescriptions.find(candidate.address);
            it != project.variableDescriptions.end())
            oldDescription = it->second;
        setVariableDescription(imported, candidate.address, candidate.description);
        if (oldName == candidate.name && oldDescription == candidate.description) {
            ++result.unchanged;
            continue;
        }
        result.changes.push_back({candidate.line, candidate.address, oldName, candidate.name,
                                  oldDescription, candidate.description});
    }
    std::stable_sort(result.problems.begin(), result.problems.end(),
                     [](const CsvProblem& a, const CsvProblem& b) {
                         return std::tie(a.line, a.column) < std::tie(b.line, b.column);
                     });
    return result;
}

} // namespace rs::project
