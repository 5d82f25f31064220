#include "Verbs.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace {

constexpr const char* kVerbs = R"(Verbs:
  check FILE.sps                 parse and check the whole project
  compile FILE.sps [-o OUT.hps]  check, then write the compiled image (Intel HEX)
  format FILE.sps                print the canonical text of the project
)";

int usage(const QString& message) {
    std::fprintf(stderr, "rungsmith-cli: %s\nTry 'rungsmith-cli --help'.\n", qPrintable(message));
    return rs::cli::UsageOrIo;
}

} // namespace

int main(int argc, char* argv[]) {
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("rungsmith-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RUNGSMITH_VERSION));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QStringLiteral("Rungsmith command line: check, compile and format Pluto programs.\n\n") +
        QString::fromUtf8(kVerbs));
    parser.addPositionalArgument(QStringLiteral("verb"),
                                 QStringLiteral("check, compile or format"));
    parser.addPositionalArgument(QStringLiteral("file"), QStringLiteral("the project file (.sps)"));
    const QCommandLineOption output({QStringLiteral("o"), QStringLiteral("output")},
                                    QStringLiteral("Where compile writes the image."),
                                    QStringLiteral("OUT.hps"));
    const QCommandLineOption noIoWarnings(
        QStringLiteral("no-io-warnings"),
        QStringLiteral("Do not warn about inputs and outputs used without an I/O declaration."));
    parser.addOption(output);
    parser.addOption(noIoWarnings);
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    if (!parser.parse(app.arguments()))
        return usage(parser.errorText());
    if (parser.isSet(help)) {
        std::fputs(qPrintable(parser.helpText()), stdout);
        return rs::cli::Ok;
    }
    if (parser.isSet(version)) {
        std::printf("rungsmith-cli %s\n", RUNGSMITH_VERSION);
        return rs::cli::Ok;
    }
    const QStringList arguments = parser.positionalArguments();
    if (arguments.isEmpty())
        return usage(QStringLiteral("missing verb"));
    const QString verb = arguments.front();
    rs::compiler::CheckOptions options;
    options.warnUnconfiguredIo = !parser.isSet(noIoWarnings);
    if (verb == QLatin1String("check") || verb == QLatin1String("format") ||
        verb == QLatin1String("compile")) {
        if (arguments.size() != 2)
            return usage(QStringLiteral("%1 takes exactly one FILE.sps").arg(verb));
        if (parser.isSet(output) && verb != QLatin1String("compile"))
            return usage(QStringLiteral("-o is an option of compile"));
        if (verb == QLatin1String("check"))
            return rs::cli::runCheck(arguments[1], options, {});
        if (verb == QLatin1String("compile"))
            return rs::cli::runCompile(arguments[1], parser.value(output), options, {});
        return rs::cli::runFormat(arguments[1], {});
    }
    return usage(QStringLiteral("unknown verb '%1'").arg(verb));
}
