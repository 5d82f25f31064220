#include "Verbs.h"

#include <QCommandLineParser>
#include <QCoreApplication>

#include <cstdio>

namespace {

constexpr const char* kVerbs = R"(Verbs:
  check FILE.sps     parse and check the whole project
  format FILE.sps    print the canonical text of the project
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
        QStringLiteral("Rungsmith command line: check and format Pluto programs.\n\n") +
        QString::fromUtf8(kVerbs));
    parser.addPositionalArgument(QStringLiteral("verb"), QStringLiteral("check or format"));
    parser.addPositionalArgument(QStringLiteral("file"), QStringLiteral("the project file (.sps)"));
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
    if (verb == QLatin1String("check") || verb == QLatin1String("format")) {
        if (arguments.size() != 2)
            return usage(QStringLiteral("%1 takes exactly one FILE.sps").arg(verb));
        return verb == QLatin1String("check") ? rs::cli::runCheck(arguments[1], {})
                                              : rs::cli::runFormat(arguments[1], {});
    }
    return usage(QStringLiteral("unknown verb '%1'").arg(verb));
}
