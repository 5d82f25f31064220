// SPDX-License-Identifier: GPL-3.0-or-later
#include "RungsmithBuildVersion.h"
#include "document/ProjectDocument.h"
#include "lang/Diagnostic.h"
#include "memory/HugePageHeap.h"
#include "output/SettledCompile.h"
#include "pl110/Pl110Document.h"
#include "pl110/Pl110Window.h"
#include "pl110/ProgramFile.h"
#include "project/SaveFileCommit.h"
#include "prove/PropertiesPage.h"
#include "shell/MainWindow.h"
#include "shell/PageRef.h"
#include "shell/Preferences.h"
#include "shell/Theme.h"
#include "shell/Translations.h"
#include "sim/SimulationMode.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDeadlineTimer>
#include <QIcon>
#include <QImageWriter>
#include <QPointer>
#include <QRegularExpression>
#include <QSaveFile>
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

struct Page {
    rs::ui::PageRef::Kind kind;
    int station;
    int sequence = 0;
};

// "ladder:N", "text:N", "io:N", "asi:N", "variables:N" and "unit:N": a page of the unit
// with station number N; "gateway:N" the gateway with node address N; "ladder:N.S" and "text:N.S"
// its sequence S, as the language writes a sequence (S0.1); "project": the project's own page;
// "properties": its properties and their proofs.
std::optional<Page> pageOf(const QString& text) {
    if (text == QLatin1String("project"))
        return Page{rs::ui::PageRef::Kind::Project, -1};
    if (text == QLatin1String("properties"))
        return Page{rs::ui::PageRef::Kind::Properties, -1};
    static const QRegularExpression form(
        QStringLiteral("^(?:(ladder|text):(\\d{1,2})(?:\\.([1-9]))?|(io|asi|variables|unit|gateway)"
                       ":(\\d{1,2}))$"));
    const QRegularExpressionMatch match = form.match(text);
    if (!match.hasMatch())
        return std::nullopt;
    const bool code = match.hasCaptured(1);
    const QString kind = code ? match.captured(1) : match.captured(4);
    using Kind = rs::ui::PageRef::Kind;
    return Page{kind == QLatin1String("ladder")    ? Kind::Ladder
                : kind == QLatin1String("text")    ? Kind::Code
                : kind == QLatin1String("io")      ? Kind::IoOptions
                : kind == QLatin1String("asi")     ? Kind::AsiOptions
                : kind == QLatin1String("unit")    ? Kind::Unit
                : kind == QLatin1String("gateway") ? Kind::Gateway
                                                   : Kind::Variables,
                (code ? match.captured(2) : match.captured(5)).toInt(),
                code && match.hasCaptured(3) ? match.captured(3).toInt() : 0};
}

std::optional<rs::ui::Preferences::Theme> themeOf(const QString& text) {
    using Theme = rs::ui::Preferences::Theme;
    if (text == QLatin1String("light"))
        return Theme::Light;
    if (text == QLatin1String("dark"))
        return Theme::Dark;
    if (text == QLatin1String("system"))
        return Theme::System;
    return std::nullopt;
}

// Prints a scenario's syntax errors as the command line does; true when it had any.
bool reportSyntaxErrors(const rs::ui::SimulationSession::ScenarioResult& result) {
    QTextStream err(stderr);
    for (const rs::lang::Diagnostic& diagnostic : result.syntaxErrors)
        err << QString::fromStdString(
                   rs::lang::formatDiagnostic(result.path.toStdString(), diagnostic))
            << '\n';
    return !result.syntaxErrors.empty();
}

// Writes the picture whole or not at all; the message when it cannot.
QString writePicture(const QImage& picture, const QString& path) {
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly))
        return CommandLine::tr("cannot write %1: %2").arg(path, file.errorString());
    QImageWriter writer(&file, "png");
    if (!writer.write(picture)) {
        file.cancelWriting();
        return CommandLine::tr("cannot write %1: %2").arg(path, writer.errorString());
    }
    const QString reason = rs::project::commitSaveFile(file);
    return reason.isEmpty() ? QString() : CommandLine::tr("cannot write %1: %2").arg(path, reason);
}

// Lets the window lay itself out and paint as it would on a screen.
void settle() {
    for (int i = 0; i < 3; ++i) {
        QCoreApplication::sendPostedEvents();
        QCoreApplication::processEvents();
    }
}

// What pages compute in the background after a change (signatures, changes
// since validation) is part of the picture; a bounded wait keeps a stuck
// computation from hanging the command.
void awaitSettledCompile(rs::ui::MainWindow& window) {
    rs::ui::ProjectDocument* document = window.currentDocument();
    if (!document)
        return;
    const rs::ui::SettledCompile* compile = rs::ui::SettledCompile::of(document);
    const QDeadlineTimer deadline(30'000);
    while (compile->isComputing() && !deadline.hasExpired())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
}

// Build > Prove All, waited for: a proof runs as long as its properties take.
void awaitProof(rs::ui::MainWindow& window) {
    window.proveAll();
    while (window.propertiesPage()->isProving())
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
}

// A PL110 program opens in its own window (docs/pl110.md, "The window"):
// ladder:N shows rung N, text:N its text, variables:N its names; the rest of
// the pages are a Pluto project's.
struct Pl110Request {
    QString path;
    std::optional<Page> page;
    QString scenario;
    QString screenshot;
};

int openPl110(const Pl110Request& request) {
    using Kind = rs::ui::PageRef::Kind;
    if (request.page && request.page->kind != Kind::Ladder && request.page->kind != Kind::Code &&
        request.page->kind != Kind::Variables)
        return usageError(CommandLine::tr("%1 is a PL110 program: its pages are ladder:N (from "
                                          "rung N), text:N and variables:N")
                              .arg(request.path));
    QString error;
    rs::ui::Pl110Document* document = rs::ui::Pl110Document::open(request.path, error);
    if (!document)
        return usageError(error);
    // The window deletes itself when the user closes it (several may be open).
    const QPointer<rs::ui::Pl110Window> window = new rs::ui::Pl110Window(document);
    const auto status = [&window](int code) {
        delete window.data();
        return code;
    };
    window->show();
    settle();
    if (request.page) {
        if (request.page->kind == Kind::Code)
            window->showPage(rs::ui::Pl110Window::Page::Program);
        else if (request.page->kind == Kind::Variables)
            window->showPage(rs::ui::Pl110Window::Page::Names);
        else if (!window->showRung(std::max(request.page->station, 1)))
            return status(usageError(
                CommandLine::tr("%1 has no rung %2").arg(request.path).arg(request.page->station)));
    }
    if (!request.scenario.isEmpty())
        if (const QString failed = window->runScenario(request.scenario); !failed.isEmpty())
            return status(usageError(failed));
    if (request.screenshot.isEmpty())
        return status(QApplication::exec());
    settle();
    if (const QString failed = writePicture(window->grab().toImage(), request.screenshot);
        !failed.isEmpty())
        return status(usageError(failed));
    return status(0);
}

} // namespace

int main(int argc, char* argv[]) {
    rs::memory::backTheHeapWithHugePages();
    QApplication application(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationName(QStringLiteral("Rungsmith"));
    QApplication::setApplicationVersion(QStringLiteral(RUNGSMITH_BUILD_VERSION));
    // Wayland finds the window's icon and name through the desktop entry.
    QGuiApplication::setDesktopFileName(QStringLiteral("io.github.rungsmith.Rungsmith"));
    QApplication::setWindowIcon(QIcon(QStringLiteral(":/icons/rungsmith.svg")));
    const rs::ui::Preferences preferences = rs::ui::Preferences::load();
    rs::ui::installTranslations(
        application, preferences.language.isEmpty() ? QLocale() : QLocale(preferences.language));

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
        CommandLine::tr("The page to show: ladder:N (the code of unit N as ladder), text:N (as "
                        "text), ladder:N.S or text:N.S (its sequence S), io:N (its I/O options), "
                        "asi:N (its AS-i options), variables:N, unit:N, gateway:N (the gateway "
                        "with node address N), project, or properties (the project's properties "
                        "and their proofs)."),
        QStringLiteral("PAGE"));
    const QCommandLineOption themeOption(
        QStringLiteral("theme"),
        CommandLine::tr("Draw with the light or dark palette, or the system's, this time."),
        QStringLiteral("light|dark|system"));
    const QCommandLineOption simulateOption(
        QStringLiteral("simulate"),
        CommandLine::tr("Run the scenario in the simulator first, so the window shows the live "
                        "state it ends in."),
        QStringLiteral("SCENARIO.scn"));
    const QCommandLineOption proveOption(
        QStringLiteral("prove"),
        CommandLine::tr("Prove the project's properties first (Build > Prove All), so the window "
                        "shows their results."));
    parser.addOptions({screenshotOption, pageOption, themeOption, simulateOption, proveOption});

    if (!parser.parse(QCoreApplication::arguments()))
        return usageError(parser.errorText());
    if (parser.isSet(helpOption))
        parser.showHelp(0);
    if (parser.isSet(versionOption)) {
        QTextStream(stdout) << "rungsmith " << QCoreApplication::applicationVersion() << '\n';
        return 0;
    }

    const QStringList files = parser.positionalArguments();
    if (files.size() > 1)
        return usageError(CommandLine::tr("give at most one project file"));
    std::optional<Page> page;
    if (parser.isSet(pageOption)) {
        page = pageOf(parser.value(pageOption));
        if (!page)
            return usageError(CommandLine::tr("unknown page '%1'; the pages are ladder:N, text:N, "
                                              "io:N, asi:N, variables:N and unit:N for unit N, "
                                              "ladder:N.S and text:N.S for its sequence S, "
                                              "gateway:N for gateway N, project and "
                                              "properties")
                                  .arg(parser.value(pageOption)));
    }
    std::optional<rs::ui::Preferences::Theme> theme = preferences.theme;
    if (parser.isSet(themeOption)) {
        theme = themeOf(parser.value(themeOption));
        if (!theme)
            return usageError(CommandLine::tr("unknown theme '%1'; use light, dark or system")
                                  .arg(parser.value(themeOption)));
    }
    if (*theme != rs::ui::Preferences::Theme::System)
        rs::ui::applyTheme(*theme);
    const QString shownFile = files.isEmpty() ? CommandLine::tr("the example") : files.first();
    const QString noSuchUnit =
        page && page->sequence != 0 ? CommandLine::tr("%1 has no sequence %2 in unit %3")
                                          .arg(shownFile)
                                          .arg(page->sequence)
                                          .arg(page->station)
        : page && page->kind == rs::ui::PageRef::Kind::Gateway
            ? CommandLine::tr("%1 has no gateway %2").arg(shownFile).arg(page->station)
        : page && page->kind == rs::ui::PageRef::Kind::Properties
            ? CommandLine::tr("%1 does not read, so it has no properties page").arg(shownFile)
            : CommandLine::tr("%1 has no unit %2").arg(shownFile).arg(page ? page->station : 0);

    if (!files.isEmpty() && rs::pl110::isPl110File(files.first())) {
        if (parser.isSet(proveOption))
            return usageError(
                CommandLine::tr("%1 is a PL110 program; proofs are for Pluto projects")
                    .arg(files.first()));
        return openPl110(
            {files.first(), page, parser.value(simulateOption), parser.value(screenshotOption)});
    }

    rs::ui::MainWindow window;
    if (parser.isSet(screenshotOption)) {
        if (files.isEmpty())
            window.showExample();
        else if (const QString error = window.loadFile(files.first()); !error.isEmpty())
            return usageError(error);
        window.show();
        settle();
        if (page && !window.showPage(page->kind, page->station, page->sequence))
            return usageError(noSuchUnit);
        if (parser.isSet(simulateOption)) {
            const auto result = window.simulation()->runScenario(parser.value(simulateOption));
            if (!result.error.isEmpty())
                return usageError(result.error);
            // A scenario that did not run shows nothing worth a picture.
            if (reportSyntaxErrors(result))
                return 1;
        }
        if (parser.isSet(proveOption))
            awaitProof(window);
        awaitSettledCompile(window);
        settle();
        if (const QString error =
                writePicture(window.grab().toImage(), parser.value(screenshotOption));
            !error.isEmpty())
            return usageError(error);
        return 0;
    }

    window.restoreLayout();
    window.show();
    window.recoverAutosaved();
    // Without a file the window starts on its welcome page, with the
    // projects opened last.
    if (!files.isEmpty())
        window.openFile(files.first());
    if (page && !window.showPage(page->kind, page->station, page->sequence))
        complain(noSuchUnit);
    if (parser.isSet(proveOption))
        window.proveAll();
    if (parser.isSet(simulateOption)) {
        QObject::connect(
            window.simulation()->session(), &rs::ui::SimulationSession::scenarioFinished, &window,
            [](const rs::ui::SimulationSession::ScenarioResult& result) {
                if (!result.error.isEmpty())
                    complain(result.error);
                reportSyntaxErrors(result);
            },
            Qt::SingleShotConnection);
        window.simulation()->startScenario(parser.value(simulateOption));
    }
    return QApplication::exec();
}
