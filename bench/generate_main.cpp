// SPDX-License-Identifier: GPL-3.0-or-later
#include "ProjectGenerator.h"

#include "project/ProjectFile.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace {

int usage(const QString& message) {
    std::fprintf(stderr, "rungsmith-generate: %s\nTry 'rungsmith-generate --help'.\n",
                 qPrintable(message));
    return 2;
}

// Reads a whole decimal option value; QString::toUInt accepts no trailing text.
bool readNumber(const QCommandLineParser& parser, const QCommandLineOption& option,
                std::uint32_t& out) {
    if (!parser.isSet(option))
        return true;
    bool ok = false;
    const uint value = parser.value(option).toUInt(&ok);
    if (ok)
        out = value;
    return ok;
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rungsmith-generate"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RUNGSMITH_VERSION));

    const rs::bench::GeneratorOptions defaults;
    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Writes a large, valid Pluto project for benchmarks. The same options "
                       "give the same file."));
    const QCommandLineOption units(
        QStringLiteral("units"),
        QStringLiteral("Number of units, 1-32 (default %1).").arg(defaults.units),
        QStringLiteral("N"));
    const QCommandLineOption statements(
        QStringLiteral("statements"),
        QStringLiteral("Statements per unit (default %1).").arg(defaults.statementsPerUnit),
        QStringLiteral("S"));
    const QCommandLineOption seed(QStringLiteral("seed"),
                                  QStringLiteral("Random seed (default %1).").arg(defaults.seed),
                                  QStringLiteral("SEED"));
    const QCommandLineOption output(QStringList{QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Write to FILE instead of standard output."),
                                    QStringLiteral("FILE"));
    parser.addOptions({units, statements, seed, output});
    parser.addHelpOption();
    parser.addVersionOption();
    parser.process(app);
    if (!parser.positionalArguments().isEmpty())
        return usage(
            QStringLiteral("unexpected argument '%1'").arg(parser.positionalArguments()[0]));

    std::uint32_t unitCount = static_cast<std::uint32_t>(defaults.units);
    std::uint32_t statementCount = static_cast<std::uint32_t>(defaults.statementsPerUnit);
    rs::bench::GeneratorOptions options;
    if (!readNumber(parser, units, unitCount) || !readNumber(parser, statements, statementCount) ||
        !readNumber(parser, seed, options.seed))
        return usage(QStringLiteral("--units, --statements and --seed take a whole number"));
    // Out-of-range counts are reported by the generator; the clamp only keeps them ints.
    options.units = static_cast<int>(std::min<std::uint32_t>(unitCount, 1000));
    options.statementsPerUnit = static_cast<int>(std::min<std::uint32_t>(statementCount, 1000000));

    std::string text;
    try {
        text = rs::bench::generateProject(options);
    } catch (const std::invalid_argument& error) {
        return usage(QString::fromUtf8(error.what()));
    }
    if (!parser.isSet(output)) {
        std::fwrite(text.data(), 1, text.size(), stdout);
        return 0;
    }
    const QString error = rs::project::writeTextFile(parser.value(output), text);
    if (!error.isEmpty()) {
        std::fprintf(stderr, "rungsmith-generate: %s\n", qPrintable(error));
        return 1;
    }
    return 0;
}
