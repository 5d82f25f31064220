// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectFile.h"

#include "Annotation.h"
#include "AsiRecords.h"
#include "Baseline.h"
#include "CanBusCycle.h"
#include "GatewayRecords.h"
#include "RecordWords.h"
#include "RemanentVariables.h"
#include "SaveFileCommit.h"
#include "WriteBehind.h"
#include "lang/NameResolver.h"
#include "lang/Parser.h"
#include "lang/Printer.h"

#include <QFile>
#include <QSaveFile>

#include <algorithm>
#include <set>
#include <tuple>

namespace rs::project {

namespace {

using lang::CommentLine;
using lang::Line;

int parseStation(const std::string& text) {
    if (text.empty() || text.size() > 2 ||
        text.find_first_not_of("0123456789") != std::string::npos)
        return -1;
    return std::stoi(text);
}

bool parseFlag(const std::string& text, bool& out) {
    if (text == "yes" || text == "true" || text == "1") {
        out = true;
        return true;
    }
    if (text == "no" || text == "false" || text == "0") {
        out = false;
        return true;
    }
    return false;
}

class AnnotationReader {
public:
    AnnotationReader(Project& project, lang::Diagnostics& diagnostics)
        : m_project(project), m_diagnostics(diagnostics) {}

    // Takes project, unit and variable records out of a list of lines.
    void take(std::vector<Line>& lines) {
        std::vector<Line> kept;
        kept.reserve(lines.size());
        for (auto& line : lines) {
            auto* comment = std::get_if<CommentLine>(&line.body);
            if (!comment || !consume(*comment, line.location))
                kept.push_back(std::move(line));
        }
        lines = std::move(kept);
    }

    // Network, block instance and system call records stay where they are;
    // they are only checked (block instances by blocks::findInstances, system
    // calls by the compiler).
    void check(const std::vector<Line>& lines) {
        for (const auto& line : lines)
            if (auto* comment = std::get_if<CommentLine>(&line.body))
                if (auto annotation = read(*comment, line.location);
                    annotation && annotation->kind != "network" && annotation->kind != "block" &&
                    annotation->kind != "end" && annotation->kind != "system")
                    warn(line.location, "@" + annotation->kind +
                                            " records belong before the code; kept as a comment");
    }

private:
    std::optional<Annotation> read(const CommentLine& comment, lang::SourceLocation at) {
        try {
            return parseAnnotation(comment.text);
        } catch (const AnnotationError& error) {
            int column = at.column + (comment.indented ? lang::kCommentColumn - at.column : 0);
            m_diagnostics.push_back(
                {lang::Severity::Error, at.line, column + 1 + error.offset, error.message});
            return std::nullopt;
        }
    }

    void warn(lang::SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Warning, at.line, at.column, std::move(message)});
    }
    void error(lang::SourceLocation at, std::string message) {
        m_diagnostics.push_back({lang::Severity::Error, at.line, at.column, std::move(message)});
    }

    bool consume(const CommentLine& comment, lang::SourceLocation at) {
        auto annotation = read(comment, at);
        if (!annotation)
            return false;
        const std::string& kind = annotation->kind;
        if (kind == "project") {
            m_project.description = annotation->value("description");
            std::string flag = annotation->value("include_source");
            if (!flag.empty() && !parseFlag(flag, m_project.includeSource))
                error(at, "include_source must be yes or no, not '" + flag + "'");
            for (const auto& [key, value] : annotation->attributes)
                if (key == "library" && !value.empty())
                    m_project.libraries.push_back(value);
            return true;
        }
        if (kind == "unit") {
            int station =
                annotation->arguments.empty() ? -1 : parseStation(annotation->arguments[0]);
            if (station < 0 || station > 31) {
                error(at, "@unit needs a station number 0-31, as in ;@unit 00 description=\"...\"");
                return false;
            }
            if (std::string description = annotation->value("description"); !description.empty())
                m_project.unitDescriptions[station] = std::move(description);
            if (std::string cycle = annotation->value("can_cycle_ms"); !cycle.empty()) {
                const auto ms = wholeNumber(cycle);
                if (!ms || *ms == 0 || setCanCycle(m_project, station, *ms))
                    error(at, "@unit can_cycle_ms must be a number of milliseconds " +
                                  std::to_string(kMinCanCycleMs) + "-" +
                                  std::to_string(kMaxCanCycleMs) + ", not '" + cycle + "'");
            }
            if (std::string idfix = annotation->value("idfix"); idfix == "prog")
                m_project.idfixProg.insert(station);
            else if (!idfix.empty())
                error(at, "@unit idfix can only be prog (an IDFIX-PROG), not '" + idfix + "'");
            if (std::string list = annotation->value("remanent"); !list.empty()) {
                try {
                    std::set<lang::Address> remanent = parseRemanentList(list, station);
                    m_project.remanentVariables.insert(remanent.begin(), remanent.end());
                } catch (const RemanentListError& problem) {
                    error(at, "@unit remanent: " + problem.message);
                }
            }
            return true;
        }
        if (kind == "var") {
            lang::AddressWord word = annotation->arguments.empty()
                                         ? lang::AddressWord{}
                                         : lang::readAddressWord(annotation->arguments[0]);
            if (word.shape != lang::AddressWord::Shape::Variable) {
                error(at, "@var needs an address, as in ;@var I0.0 description=\"...\"");
                return false;
            }
            if (std::string description = annotation->value("description"); !description.empty())
                m_project.variableDescriptions[word.address] = std::move(description);
            bool exported = false;
            if (std::string flag = annotation->value("export");
                !flag.empty() && !parseFlag(flag, exported))
                error(at, "export must be yes or no, not '" + flag + "'");
            if (exported)
                m_project.exportedVariables.insert(word.address);
            return true;
        }
        if (kind == "validated") {
            Baseline baseline = m_project.baseline.value_or(Baseline{});
            try {
                readBaselineRecord(*annotation, baseline);
            } catch (const BaselineRecordError& problem) {
                error(at, problem.message);
                return false;
            }
            m_project.baseline = std::move(baseline);
            return true;
        }
        if (kind == "asi" || kind == "asi_slave") {
            try {
                readAsiRecord(*annotation, m_project.asiOptions);
            } catch (const AsiRecordError& problem) {
                error(at, problem.message);
                return false;
            }
            return true;
        }
        if (kind == "ext_comm") {
            try {
                readExternalCommRecord(*annotation, m_project.externalComm);
            } catch (const ExternalCommRecordError& problem) {
                error(at, problem.message);
                return false;
            }
            return true;
        }
        if (kind == "gateway" || kind == "gateway_area") {
            try {
                readGatewayRecord(*annotation, m_project.gateways);
            } catch (const GatewayRecordError& problem) {
                error(at, problem.message);
                return false;
            }
            return true;
        }
        if (kind == "protected") {
            try {
                m_project.protection = readProtectionRecord(*annotation);
            } catch (const ProtectionRecordError& problem) {
                error(at, problem.message);
                return false;
            }
            return true;
        }
        if (kind != "network")
            warn(at, "unknown record '@" + kind + "'; kept as a comment");
        return false;
    }

    Project& m_project;
    lang::Diagnostics& m_diagnostics;
};

Line commentLine(const Annotation& annotation) {
    return {CommentLine{formatAnnotation(annotation), false}, std::nullopt, {}};
}

bool isIdOf(const Line& line, int station) {
    if (auto* declaration = std::get_if<lang::Declaration>(&line.body))
        if (auto* id = std::get_if<lang::IdDeclaration>(&declaration->body))
            return id->station == station;
    return false;
}

// The records of one unit: its description and remanent variables, then its
// variables' descriptions and export marks, then its AS-i options and its
// External communication setting.
std::vector<Line> unitRecords(const Project& project, int station) {
    std::vector<Line> lines;
    Annotation unit{"unit", {stationText(station)}, {}};
    if (auto it = project.unitDescriptions.find(station);
        it != project.unitDescriptions.end() && !it->second.empty())
        unit.attributes.emplace_back("description", it->second);
    if (project.idfixProg.count(station))
        unit.attributes.emplace_back("idfix", "prog");
    if (const int cycle = canCycleOf(project, station))
        unit.attributes.emplace_back("can_cycle_ms", std::to_string(cycle));
    if (std::string remanent = formatRemanentList(project.remanentVariables, station);
        !remanent.empty())
        unit.attributes.emplace_back("remanent", std::move(remanent));
    if (!unit.attributes.empty())
        lines.push_back(commentLine(unit));
    std::set<lang::Address> variables;
    for (const auto& [address, description] : project.variableDescriptions)
        if (address.unit == station && !description.empty())
            variables.insert(address);
    for (const auto& address : project.exportedVariables)
        if (address.unit == station)
            variables.insert(address);
    for (const auto& address : variables) {
        Annotation record{"var", {lang::toString(address)}, {}};
        if (auto it = project.variableDescriptions.find(address);
            it != project.variableDescriptions.end() && !it->second.empty())
            record.attributes.emplace_back("description", it->second);
        if (project.exportedVariables.count(address))
            record.attributes.emplace_back("export", "yes");
        lines.push_back(commentLine(record));
    }
    if (auto it = project.asiOptions.find(station); it != project.asiOptions.end())
        for (const Annotation& record : asiRecords(station, it->second))
            lines.push_back(commentLine(record));
    if (auto it = project.externalComm.find(station); it != project.externalComm.end())
        for (const Annotation& record : externalCommRecords(station, it->second))
            lines.push_back(commentLine(record));
    return lines;
}

} // namespace

ProjectReadResult readProject(std::string_view text) {
    lang::ParseResult parsed = lang::parse(text);
    ProjectReadResult result;
    result.project.program = std::move(parsed.document);
    result.diagnostics = std::move(parsed.diagnostics);
    AnnotationReader records(result.project, result.diagnostics);
    records.take(result.project.program.preamble);
    for (auto& unit : result.project.program.units) {
        records.take(unit.declarations);
        for (const auto& step : unit.steps)
            records.check(step.lines);
    }
    std::erase_if(result.project.asiOptions,
                  [](const auto& entry) { return entry.second == AsiOptions{}; });
    auto resolved = lang::resolveNames(result.project.program);
    result.diagnostics.insert(result.diagnostics.end(), resolved.begin(), resolved.end());
    std::stable_sort(result.diagnostics.begin(), result.diagnostics.end(),
                     [](const lang::Diagnostic& a, const lang::Diagnostic& b) {
                         return std::tie(a.line, a.column) < std::tie(b.line, b.column);
                     });
    return result;
}

std::string writeProject(const Project& project, std::size_t expectedSize) {
    // The records go into copies of the preamble and the units' declarations;
    // the units' code, nearly all of a large project, is printed where it is.
    std::vector<Line> preamble = project.program.preamble;
    std::vector<std::vector<Line>> declarations;
    for (const auto& unit : project.program.units)
        declarations.push_back(unit.declarations);

    // Project record right after "$name" (or first).
    std::size_t at = 0;
    for (std::size_t i = 0; i < preamble.size(); ++i)
        if (std::holds_alternative<lang::Directive>(preamble[i].body))
            at = i + 1;
    if (!project.description.empty() || project.includeSource || !project.libraries.empty()) {
        Annotation record{"project", {}, {}};
        if (!project.description.empty())
            record.attributes.emplace_back("description", project.description);
        if (project.includeSource)
            record.attributes.emplace_back("include_source", "yes");
        for (const auto& library : project.libraries)
            record.attributes.emplace_back("library", library);
        preamble.insert(preamble.begin() + static_cast<std::ptrdiff_t>(at++), commentLine(record));
    }
    // Password protection after it; sealing fills in its signatures (ProtectedText.h).
    if (project.protection)
        preamble.insert(preamble.begin() + static_cast<std::ptrdiff_t>(at++),
                        commentLine(protectionRecord(*project.protection)));
    // The validated version's records after it.
    if (project.baseline)
        for (const Annotation& record : baselineRecords(*project.baseline))
            preamble.insert(preamble.begin() + static_cast<std::ptrdiff_t>(at++),
                            commentLine(record));
    // The gateways on the bus, by node address.
    for (const auto& [node, gateway] : project.gateways)
        for (const Annotation& record : gatewayRecords(node, gateway))
            preamble.insert(preamble.begin() + static_cast<std::ptrdiff_t>(at++),
                            commentLine(record));

    // Unit records after the unit's id declaration, else first in its code.
    std::set<int> stations;
    for (const auto& [station, text] : project.unitDescriptions)
        stations.insert(station);
    stations.insert(project.idfixProg.begin(), project.idfixProg.end());
    for (const auto& [station, ms] : project.canCycleMs)
        stations.insert(station);
    for (const auto& [station, options] : project.asiOptions)
        stations.insert(station);
    for (const auto& [station, comm] : project.externalComm)
        stations.insert(station);
    for (const auto& [address, text] : project.variableDescriptions)
        stations.insert(address.unit);
    for (const auto* addresses : {&project.exportedVariables, &project.remanentVariables})
        for (const auto& address : *addresses)
            stations.insert(address.unit);
    for (int station : stations) {
        std::vector<Line> records = unitRecords(project, station);
        if (records.empty())
            continue;
        auto id = std::find_if(preamble.begin(), preamble.end(),
                               [&](const Line& line) { return isIdOf(line, station); });
        if (id != preamble.end()) {
            preamble.insert(id + 1, records.begin(), records.end());
            continue;
        }
        const auto& units = project.program.units;
        auto unit = std::find_if(units.begin(), units.end(),
                                 [&](const auto& u) { return u.station() == station; });
        if (unit != units.end()) {
            auto& own = declarations[static_cast<std::size_t>(unit - units.begin())];
            own.insert(own.begin(), records.begin(), records.end());
        } else {
            preamble.insert(preamble.end(), records.begin(), records.end());
        }
    }
    return lang::print(preamble, project.program.units, declarations, expectedSize);
}

namespace {

// Byte-order marks of the encodings a reader refuses, longest first: the
// UTF-32 little-endian mark begins with the UTF-16 one.
struct RefusedMark {
    std::string_view bytes;
    const char* encoding;
};
constexpr RefusedMark kRefusedMarks[] = {
    {std::string_view("\xFF\xFE\x00\x00", 4), "UTF-32"},
    {std::string_view("\x00\x00\xFE\xFF", 4), "UTF-32"},
    {"\xFF\xFE", "UTF-16"},
    {"\xFE\xFF", "UTF-16"},
};
constexpr std::string_view kUtf8Mark = "\xEF\xBB\xBF";

} // namespace

FileText readTextFile(const QString& path, qint64 maxBytes) {
    QFile file(path);
    const auto failure = [&](const QString& reason) {
        return FileText{{}, QStringLiteral("cannot read %1: %2").arg(path, reason)};
    };
    if (!file.open(QIODevice::ReadOnly))
        return failure(file.errorString());
    // Read in pieces up to one byte past the limit: the size a device reports
    // cannot be trusted (/dev/zero, a pipe, a file that grows).
    constexpr qint64 kPiece = 1 << 20;
    std::string text;
    if (!file.isSequential())
        text.reserve(static_cast<std::size_t>(std::min(file.size(), maxBytes) + 1));
    for (;;) {
        const std::size_t used = text.size();
        qint64 room = std::min<qint64>(kPiece, maxBytes + 1 - static_cast<qint64>(used));
        if (room <= 0)
            break;
        // Within what was reserved while it lasts: the byte reserved past the
        // reported size finds the end without the string doubling.
        if (text.capacity() > used)
            room = std::min<qint64>(room, static_cast<qint64>(text.capacity() - used));
        text.resize(used + static_cast<std::size_t>(room));
        const qint64 got = file.read(text.data() + used, room);
        text.resize(used + static_cast<std::size_t>(std::max<qint64>(got, 0)));
        if (got < 0)
            return failure(file.errorString());
        if (got == 0)
            break;
    }
    if (static_cast<qint64>(text.size()) > maxBytes)
        return {{},
                QStringLiteral("%1: larger than %2 MB, the most Rungsmith reads from one file")
                    .arg(path)
                    .arg(maxBytes / (1024 * 1024))};
    for (const RefusedMark& mark : kRefusedMarks)
        if (text.starts_with(mark.bytes))
            return {{},
                    QStringLiteral("%1: %2 text is not supported; save it as UTF-8")
                        .arg(path, QLatin1String(mark.encoding))};
    if (text.starts_with(kUtf8Mark))
        text.erase(0, kUtf8Mark.size());
    return {std::move(text), {}};
}

namespace {

// After the writing: a failure cancels the file, else it is committed; the
// reason of either, as writeTextFile says it.
QString settleSaveFile(QSaveFile& file, const QString& path, const QString& writeError) {
    QString reason = writeError;
    if (reason.isEmpty())
        reason = commitSaveFile(file);
    else
        file.cancelWriting();
    return reason.isEmpty() ? QString() : QStringLiteral("cannot write %1: %2").arg(path, reason);
}

} // namespace

QString writeTextFile(const QString& path, std::string_view text) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    const bool whole = file.write(text.data(), static_cast<qint64>(text.size())) ==
                       static_cast<qint64>(text.size());
    return settleSaveFile(file, path, whole ? QString() : file.errorString());
}

QString writeTextFile(const QString& path, const std::function<void(const TextSink&)>& write) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return QStringLiteral("cannot write %1: %2").arg(path, file.errorString());
    QString error;
    {
        // Should `write` throw, the pieces still queued are dropped here and
        // QSaveFile removes its temporary copy.
        WriteBehind writer(file);
        write([&writer](std::string_view piece) { writer.add(piece); });
        error = writer.finish();
    }
    return settleSaveFile(file, path, error);
}

} // namespace rs::project
