// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlocksVerbs.h"
#include "Drawing.h"
#include "Invocation.h"
#include "LadderVerbs.h"
#include "MergeVerb.h"
#include "Pl110Verbs.h"
#include "ProtectVerb.h"
#include "ProveVerb.h"
#include "ReviewVerbs.h"
#include "RungsmithBuildVersion.h"
#include "ServeVerb.h"
#include "TestVerb.h"
#include "VarsVerbs.h"
#include "Verbs.h"
#include "lang/Diagnostic.h"
#include "memory/HugePageHeap.h"
#include "pl110/ProgramFile.h"

#include <QCoreApplication>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>

namespace {

using rs::cli::Invocation;
using rs::cli::usage;

// Output to a pipe or a redirected file is buffered: a full disk or a closed
// pipe shows only at the flush, and must not pass as success.
int finishOutput(int status) {
    if (std::fflush(stdout) == 0 && !std::ferror(stdout))
        return status;
    std::fprintf(stderr, "rungsmith-cli: cannot write the standard output: %s\n",
                 std::strerror(errno));
    return rs::cli::UsageOrIo;
}

rs::compiler::CheckOptions checkOptions(const Invocation& invocation) {
    rs::compiler::CheckOptions options;
    options.warnUnconfiguredIo = !invocation.options.isSet(QStringLiteral("no-io-warnings"));
    return options;
}

int check(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("check takes exactly one FILE.sps"));
    if (const auto text = rs::cli::pl110Text(invocation.arguments[0]))
        return rs::cli::checkPl110(invocation.arguments[0], *text);
    return rs::cli::runCheck(invocation.arguments[0], rs::cli::libraryFiles(invocation),
                             checkOptions(invocation), {});
}

int compile(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("compile takes exactly one FILE.sps"));
    return rs::cli::runCompile(invocation.arguments[0],
                               invocation.options.value(QStringLiteral("output")),
                               rs::cli::libraryFiles(invocation), checkOptions(invocation), {});
}

int format(const Invocation& invocation) {
    if (invocation.arguments.size() != 1)
        return usage(QStringLiteral("format takes exactly one FILE.sps"));
    if (const auto text = rs::cli::pl110Text(invocation.arguments[0]))
        return rs::cli::formatPl110(invocation.arguments[0], *text);
    return rs::cli::runFormat(invocation.arguments[0], rs::cli::libraryFiles(invocation), {});
}

int test(const Invocation& invocation) {
    if (invocation.arguments.size() < 2)
        return usage(QStringLiteral("test takes FILE.sps and at least one SCENARIO.scn"));
    return rs::cli::runTest(invocation.arguments[0], invocation.arguments.mid(1),
                            invocation.options.value(QStringLiteral("vcd")),
                            rs::cli::libraryFiles(invocation), checkOptions(invocation));
}

// Every verb of the command line; --help lists them in this order.
const rs::cli::Verb kVerbs[] = {
    {"check", "check FILE.sps                 parse and check the whole project", check,
     rs::cli::Targets::PlutoAndPl110},
    {"compile", "compile FILE.sps [-o OUT.hps]  check, then write the compiled image (Intel HEX)",
     compile},
    {"format", "format FILE.sps                print the canonical text of the project", format,
     rs::cli::Targets::PlutoAndPl110},
    {"test",
     "test FILE.sps SCENARIO... [--vcd OUT.vcd]  run scenario files on the simulated project", test,
     rs::cli::Targets::PlutoAndPl110},
    {"vars",
     "vars export FILE.sps -o OUT.csv  variable names and descriptions to CSV\n"
     "  vars import FILE.sps IN.csv -o OUT.sps  names and descriptions from CSV into the project",
     rs::cli::runVars, rs::cli::Targets::PlutoAndPl110},
    {"ladder",
     "ladder FILE.sps --unit U [--sequence S --step N] --network K -o OUT.svg|.png\n"
     "                                 draw one network as the editor does\n"
     "  ladder FILE.sps ... --scenario SCN.scn  draw it in the state the scenario ends in",
     rs::cli::runLadder, rs::cli::Targets::PlutoAndPl110},
    {"roundtrip",
     "roundtrip FILE.sps             every network to the ladder model and back; print the text",
     rs::cli::runRoundtrip},
    {"signature",
     "signature FILE.sps|FILE.hps    each unit's program signature, then the project's",
     rs::cli::runSignature},
    {"diff",
     "diff OLD.sps NEW.sps [--pdf OUT.pdf]  what changed, unit by unit and network by\n"
     "                                 network, and whether the behaviour did (exit 0 no, 1 yes)",
     rs::cli::runDiff},
    {"validate",
     "validate FILE.sps --by NAME [--comment TEXT] [--date YYYY-MM-DD] -o OUT.sps\n"
     "                                 record the project's current version as validated",
     rs::cli::runValidate},
    {"review",
     "review FILE.sps                what changed since the project was validated (exit 0\n"
     "                                 none in behaviour, 1 some)",
     rs::cli::runReview},
    {"merge",
     "merge A.sps B.sps -o OUT.sps [--ignore-conflicts]\n"
     "                                 A with the units of B added (the manual's Merge Project)",
     rs::cli::runMerge},
    {"protect",
     "protect FILE.sps -o OUT.sps --password-file F [--options main|free|own]\n"
     "        [--options-password-file G] [--remove] [--accept-changes]\n"
     "                                 password protect the project (the manual's 4.1): it\n"
     "                                 reads freely, and writes only with the password",
     rs::cli::runProtect},
    {"prove",
     "prove FILE.sps PROPS.prop [--cex DIR] [--depth N]\n"
     "                                 prove each property for every input sequence, or write\n"
     "                                 the one that breaks it as a scenario (default folder .)",
     rs::cli::runProve},
    {"serve",
     "serve FILE.sps [--modbus HOST:PORT] [--scenario SCN.scn] [--speed FACTOR]\n"
     "                                 simulate in real time and serve the project's Ethernet\n"
     "                                 gateway's Modbus TCP map (default 127.0.0.1:1502)",
     rs::cli::runServe, rs::cli::Targets::PlutoAndPl110},
    {"blocks",
     "blocks list [--lib NAME|FILE]...  one line per library block: library, name(inputs -> "
     "outputs)\n"
     "  blocks show NAME [--lib NAME|FILE]... [--language en|sv|de]\n"
     "                                 a block's pins, description and body",
     rs::cli::runBlocks},
};

int run(int argc, char* argv[]) {
    const auto app = rs::cli::makeApplication(argc, argv);
    if (!app)
        return rs::cli::UsageOrIo;
    QCoreApplication::setApplicationName(QStringLiteral("rungsmith-cli"));
    QCoreApplication::setApplicationVersion(QStringLiteral(RUNGSMITH_BUILD_VERSION));

    QString description =
        QStringLiteral("Rungsmith command line for Pluto safety PLC projects.\n\nVerbs:\n");
    for (const auto& verb : kVerbs)
        description += QStringLiteral("  %1\n").arg(QString::fromUtf8(verb.synopsis));
    QCommandLineParser parser;
    parser.setApplicationDescription(description);
    parser.addPositionalArgument(QStringLiteral("verb"), QStringLiteral("what to do (see Verbs)"));
    parser.addPositionalArgument(QStringLiteral("arguments"), QStringLiteral("the verb's files"),
                                 QStringLiteral("[arguments...]"));
    parser.addOption({{QStringLiteral("o"), QStringLiteral("output")},
                      QStringLiteral("Where the verb writes its result."),
                      QStringLiteral("FILE")});
    parser.addOption({QStringLiteral("vcd"),
                      QStringLiteral("test: write a trace of the run that GTKWave opens."),
                      QStringLiteral("OUT.vcd")});
    parser.addOption({QStringLiteral("unit"), QStringLiteral("ladder: the unit's station number."),
                      QStringLiteral("U")});
    parser.addOption({QStringLiteral("sequence"),
                      QStringLiteral("ladder: the sequence (with --step; default the PLC code)."),
                      QStringLiteral("S")});
    parser.addOption({QStringLiteral("step"), QStringLiteral("ladder: the step in the sequence."),
                      QStringLiteral("N")});
    parser.addOption({QStringLiteral("network"),
                      QStringLiteral("ladder: the network's number in its step, from 1."),
                      QStringLiteral("K")});
    parser.addOption({QStringLiteral("scenario"),
                      QStringLiteral("ladder: run this scenario first and draw the power it "
                                     "leaves; serve: drive the inputs by its lines on the "
                                     "simulated clock."),
                      QStringLiteral("SCN.scn")});
    parser.addOption({QStringLiteral("lib"),
                      QStringLiteral("Add the user library FILE (.rslib) to the project's "
                                     "libraries; blocks: look only at the library NAME. "
                                     "Repeatable."),
                      QStringLiteral("NAME|FILE")});
    parser.addOption({QStringLiteral("language"),
                      QStringLiteral("blocks: the language of block descriptions: en (default), "
                                     "sv or de."),
                      QStringLiteral("LANG")});
    parser.addOption({QStringLiteral("pdf"),
                      QStringLiteral("diff: also draw each changed network old beside new, on "
                                     "pages to sign."),
                      QStringLiteral("OUT.pdf")});
    parser.addOption({QStringLiteral("by"),
                      QStringLiteral("validate: who reviewed and validated the project."),
                      QStringLiteral("NAME")});
    parser.addOption({QStringLiteral("comment"),
                      QStringLiteral("validate: what the validation was (a report, a ticket)."),
                      QStringLiteral("TEXT")});
    parser.addOption({QStringLiteral("date"),
                      QStringLiteral("validate: the date of the validation (default today)."),
                      QStringLiteral("YYYY-MM-DD")});
    parser.addOption({QStringLiteral("ignore-conflicts"),
                      QStringLiteral("merge: allow a symbolic name both projects use; it stays "
                                     "only in the units that define it.")});
    parser.addOption({QStringLiteral("password-file"),
                      QStringLiteral("The main password of a protected project, as the first "
                                     "line of FILE: every verb that writes a protected project "
                                     "needs it."),
                      QStringLiteral("FILE")});
    parser.addOption({QStringLiteral("options-password-file"),
                      QStringLiteral("protect: the Config Options' own password (with --options "
                                     "own)."),
                      QStringLiteral("FILE")});
    parser.addOption({QStringLiteral("options"),
                      QStringLiteral("protect: who may change the Config Options: main (with "
                                     "the main password, default), free (anybody), own (with "
                                     "their own password)."),
                      QStringLiteral("main|free|own")});
    parser.addOption(
        {QStringLiteral("remove"), QStringLiteral("protect: take the password protection off.")});
    parser.addOption({QStringLiteral("accept-changes"),
                      QStringLiteral("protect: take a change made by hand since the project was "
                                     "protected as the password holder's, once reviewed.")});
    parser.addOption({QStringLiteral("modbus"),
                      QStringLiteral("serve: where to answer Modbus TCP (default "
                                     "127.0.0.1:1502)."),
                      QStringLiteral("HOST:PORT")});
    parser.addOption({QStringLiteral("modbus-rtu"),
                      QStringLiteral("serve: a PL110 program's Modbus RTU slave map on a "
                                     "pseudo-terminal; the device path is printed.")});
    parser.addOption({QStringLiteral("slave"),
                      QStringLiteral("serve --modbus-rtu: the slave address to answer as "
                                     "(1-247, default 1)."),
                      QStringLiteral("ADDRESS")});
    parser.addOption({QStringLiteral("speed"),
                      QStringLiteral("serve: run the simulation FACTOR times real time."),
                      QStringLiteral("FACTOR")});
    parser.addOption({QStringLiteral("cex"),
                      QStringLiteral("prove: the folder for counterexamples and witnesses, as "
                                     "scenarios (default the current folder)."),
                      QStringLiteral("DIR")});
    parser.addOption({QStringLiteral("depth"),
                      QStringLiteral("prove: how many scans to search at most (default 200)."),
                      QStringLiteral("N")});
    parser.addOption({QStringLiteral("no-io-warnings"),
                      QStringLiteral("Do not warn about inputs and outputs used without an I/O "
                                     "declaration.")});
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    if (!parser.parse(app->arguments()))
        return usage(parser.errorText());
    if (parser.isSet(help)) {
        std::fputs(qPrintable(parser.helpText()), stdout);
        return rs::cli::Ok;
    }
    if (parser.isSet(version)) {
        std::printf("rungsmith-cli %s\n", RUNGSMITH_BUILD_VERSION);
        return rs::cli::Ok;
    }
    QStringList arguments = parser.positionalArguments();
    if (arguments.isEmpty())
        return usage(QStringLiteral("missing verb"));
    const QString name = arguments.takeFirst();
    for (const auto& verb : kVerbs) {
        if (name != QLatin1String(verb.name))
            continue;
        // A PL110 program read as a Pluto project would be a wall of wrong errors.
        if (verb.targets == rs::cli::Targets::PlutoOnly)
            for (const QString& argument : arguments)
                if (rs::pl110::isPl110File(argument))
                    return usage(QStringLiteral("%1 takes Pluto projects; %2 is a PL110 program "
                                                "(docs/pl110.md lists the verbs for one)")
                                     .arg(name, argument));
        return finishOutput(verb.run({arguments, parser}));
    }
    return usage(QStringLiteral("unknown verb '%1'").arg(name));
}

} // namespace

int main(int argc, char* argv[]) {
    // A last resort: a bug must end with a message and the exit code of a
    // failure the user cannot fix, not with an abort.
    rs::memory::backTheHeapWithHugePages();
    try {
        return run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "rungsmith-cli: internal error: %s\n",
                     rs::lang::visibleText(error.what()).c_str());
    } catch (...) {
        std::fprintf(stderr, "rungsmith-cli: internal error: unknown exception\n");
    }
    return rs::cli::UsageOrIo;
}
