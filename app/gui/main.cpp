#include "MainWindow.h"
#include "Translations.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QImageWriter>
#include <QRegularExpression>
#include <QTextStream>

#include <optional>

namespace {

// The translation context of the command-line help and messages.
class CommandLine {
    Q_DECLARE_TR_FUNCTIONS(CommandLine)
};

void complain(const QString& message) {
    QTextStream(stderr) << "rungsmith: " << message << '\n';
}

// The command-line contract's exit status for bad arguments and unreadable files.
int usageError(const QString& message) {
    complain(message);
    return 2;
}

// "text:N" is the program text of the unit with station number N. The other
// pages of the command-line contract (ladder, io, variables) arrive with
// their editors.
std::optional<int> textPageStation(const QString& page) {
    static const QRegularExpression form(QStringLiteral("^text:(\\d{1,2})$"));
    const QRegularExpressionMatch match = form.match(page);
    if (!match.hasMatch())
        return std::nullopt;
    return match.captured(1).toInt();
}

// Lets the window lay itself out and paint as it would on a screen.
void settle() {
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
}

} // namespace

int main(int argc, char* argv[]) {
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationVersion(QStringLiteral(RUNGSMITH_VERSION));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/rungsmith.svg")));
    rs::ui::installTranslations(application);

    QCommandLineParser parser;
    parser.setApplicationDescription(CommandLine::tr("IDE for Pluto safety PLCs."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    parser.addPositionalArgument(
        QStringLiteral("FILE.sps"),
        CommandLine::tr("The project to open. Without it, the bundled example opens."),
        QStringLiteral("[FILE.sps]"));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"),
        CommandLine::tr("Save a picture of the main window to OUT.png and exit."),
        QStringLiteral("OUT.png"));
    const QCommandLineOption pageOption(
        QStringLiteral("page"),
        CommandLine::tr("The page to show: text:N, the program text of unit N."),
        QStringLiteral("PAGE"));
    parser.addOptions({screenshotOption, pageOption});

    if (!parser.parse(QCoreApplication::arguments()))
        return usageError(parser.errorText());
    if (parser.isSet(helpOption))
        parser.showHelp(0);
    if (parser.isSet(versionOption))
        parser.showVersion();

    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return usageError(CommandLine::tr("give at most one project file"));
    std::optional<int> station;
    if (parser.isSet(pageOption)) {
        station = textPageStation(parser.value(pageOption));
        if (!station)
            return usageError(CommandLine::tr("unknown page '%1'; the pages so far are text:N, the "
                                              "program text of unit N")
                                  .arg(parser.value(pageOption)));
    }
    const QString shownFile = files.isEmpty() ? CommandLine::tr("the example") : files.first();
    const QString noSuchUnit =
        CommandLine::tr("%1 has no unit %2").arg(shownFile).arg(station.value_or(0));

    rs::ui::MainWindow window;
    if (parser.isSet(screenshotOption)) {
        if (files.isEmpty())
            window.showExample();
        else if (const QString error = window.loadFile(files.first()); !error.isEmpty())
            return usageError(error);
        window.show();
        settle();
        if (station && !window.showUnit(*station))
            return usageError(noSuchUnit);
        settle();
        const QString out = parser.value(screenshotOption);
        QImageWriter writer(out, "png");
        if (!writer.write(window.grab().toImage()))
            return usageError(
                CommandLine::tr("cannot write %1: %2").arg(out, writer.errorString()));
        return 0;
    }

    window.restoreLayout();
    window.show();
    if (files.isEmpty())
        window.showExample();
    else
        window.openFile(files.first());
    if (station && !window.showUnit(*station))
        complain(noSuchUnit);
    return QApplication::exec();
}
