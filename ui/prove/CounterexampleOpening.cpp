// SPDX-License-Identifier: GPL-3.0-or-later
#include "prove/CounterexampleOpening.h"

#include "document/ProjectDocument.h"
#include "ladder/LadderPage.h"
#include "project/ProjectFile.h"
#include "project/Sequences.h"
#include "prove/ProofRun.h"
#include "shell/MainWindow.h"
#include "sim/SimulationMode.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>
#include <QTemporaryDir>

namespace rs::ui {

namespace {

// The operand of the scenario's last line, "expect OPERAND VALUE".
lang::Address expectedOperand(const QString& scenario) {
    static const QRegularExpression expect(QStringLiteral("^\\s*expect\\s+(\\S+)"),
                                           QRegularExpression::CaseInsensitiveOption);
    const QStringList lines = scenario.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    if (lines.isEmpty())
        return {};
    const QRegularExpressionMatch match = expect.match(lines.back());
    if (!match.hasMatch())
        return {};
    const lang::AddressWord word = lang::readAddressWord(match.captured(1).toStdString());
    return word.shape == lang::AddressWord::Shape::Variable ? word.address : lang::Address{};
}

QString folderFor(const ProjectDocument& document) {
    const QString properties = document.propertiesPath();
    if (!properties.isEmpty())
        return QFileInfo(properties).absolutePath();
    // A project without a file of its own: the scenarios last as long as the window.
    static QTemporaryDir temporary;
    return temporary.path();
}

// The unit's code, or the first of its sequences, that has the operand.
void showOperand(MainWindow& window, ProjectDocument* document, const lang::Address& operand) {
    std::vector<int> sequences{0};
    for (int sequence : project::sequencesOf(document->project(), operand.unit))
        sequences.push_back(sequence);
    for (int sequence : sequences)
        if (window.showPage({PageRef::Kind::Ladder, document, operand.unit, sequence}) &&
            window.ladderPage()->selectOperand(operand))
            return;
    window.showPage({PageRef::Kind::Ladder, document, operand.unit, 0});
}

} // namespace

QString openCounterexample(MainWindow& window, ProjectDocument* document,
                           const PropertyProof& proof, QString& error) {
    if (!document || proof.scenario.isEmpty()) {
        error = ProofRun::tr("The property has no counterexample to open.");
        return {};
    }
    SimulationSession* session = window.simulation()->session();
    if (session->isRunningScenario()) {
        error = ProofRun::tr("A scenario is running already.");
        return {};
    }
    const QString base =
        QFileInfo(document->propertiesPath().isEmpty() ? document->displayName()
                                                       : document->propertiesPath())
            .completeBaseName();
    const QString path =
        QDir(folderFor(*document)).filePath(QStringLiteral("%1-%2.scn").arg(base).arg(proof.line));
    error = project::writeTextFile(path, proof.scenario.toStdString());
    if (!error.isEmpty())
        return {};
    // The scenario runs on the window's current project.
    if (window.currentDocument() != document &&
        !window.showPage({PageRef::Kind::Properties, document}))
        return {};
    const lang::Address operand = expectedOperand(proof.scenario);
    QObject::connect(
        session, &SimulationSession::scenarioFinished, &window,
        [&window, document = QPointer<ProjectDocument>(document), path,
         operand](const SimulationSession::ScenarioResult& result) {
            if (result.path == path && result.error.isEmpty() && !result.cancelled && document &&
                operand.valid())
                showOperand(window, document, operand);
        },
        Qt::SingleShotConnection);
    window.simulation()->startScenario(path);
    return path;
}

} // namespace rs::ui
