// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockDocumentation.h"

#include "BlockText.h"

#include <QDir>
#include <QFileInfo>

namespace rs::ui {

namespace {

QString escaped(const std::string& text) {
    return QString::fromStdString(text).toHtmlEscaped();
}

QString code(const std::string& text) {
    return QStringLiteral("<code>%1</code>").arg(escaped(text));
}

QString heading(const QString& text) {
    return QStringLiteral("<h3>%1</h3>").arg(text.toHtmlEscaped());
}

// A description's lines joined into paragraphs: a line ending in a full
// stop ends its paragraph.
QString paragraphs(const QString& text) {
    QString html;
    QString paragraph;
    for (const QString& line : text.split(QLatin1Char('\n'))) {
        paragraph += (paragraph.isEmpty() ? QString() : QStringLiteral(" ")) + line.trimmed();
        if (paragraph.endsWith(QLatin1Char('.'))) {
            html += QStringLiteral("<p>%1</p>").arg(paragraph.toHtmlEscaped());
            paragraph.clear();
        }
    }
    if (!paragraph.isEmpty())
        html += QStringLiteral("<p>%1</p>").arg(paragraph.toHtmlEscaped());
    return html;
}

const char* const kTable = "<table border=\"1\" cellspacing=\"0\" cellpadding=\"4\">";

} // namespace

QUrl BlockDocumentation::timingDiagramUrl() {
    return QUrl(QStringLiteral("rungsmith:timing-diagram"));
}

QString BlockDocumentation::html(const blocks::LoadedLibrary& library,
                                 const blocks::BlockDefinition& block,
                                 const blockdoc::TimingExample& example) {
    QString text = QStringLiteral("<h2>%1</h2>").arg(escaped(block.name));
    text += QStringLiteral("<p>%1</p>")
                .arg(tr("Library %1, version %2. Block version %3.")
                         .arg(QString::fromStdString(library.library.name),
                              QString::fromStdString(library.library.version),
                              QString::fromStdString(block.version))
                         .toHtmlEscaped());
    if (block.kind == blocks::BlockKind::System)
        text += QStringLiteral("<p><i>%1</i></p>")
                    .arg(tr("A system block: the simulator carries out its instruction %1, which "
                            "the language cannot say.")
                             .arg(QString::fromStdString(block.systemInstruction))
                             .toHtmlEscaped());
    text += paragraphs(BlockText::description(block));
    text += pinsTable(block);
    text += timingSection(library, block, example);
    const blockdoc::StateMachineTable table = blockdoc::stateMachineOf(block);
    if (!table.empty()) {
        text += statesTable(block, table);
        text += transitionsTable(table);
    }
    return text;
}

QString BlockDocumentation::pinsTable(const blocks::BlockDefinition& block) {
    QString text = heading(tr("Pins"));
    text += QString::fromLatin1(kTable);
    text += QStringLiteral("<tr><th>%1</th><th>%2</th><th>%3</th></tr>")
                .arg(tr("Pin"), tr("Kind"), tr("When not bound"));
    for (const blocks::Pin& pin : block.pins) {
        const bool input = pin.direction == blocks::PinDirection::In;
        QString open;
        if (input && pin.defaultValue)
            open = tr("default %1").arg(QString::fromStdString(*pin.defaultValue));
        else if (input)
            open = tr("must be bound");
        else if (pin.role == blocks::PinRole::Secondary)
            open = tr("may stay open");
        else
            open = tr("must be bound");
        // The summary's first two parts are direction and kind.
        const QStringList summary = BlockText::pinSummary(pin).split(QStringLiteral(", "));
        text += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td><td>%3</td></tr>")
                    .arg(escaped(pin.name),
                         summary.mid(0, 2).join(QStringLiteral(", ")).toHtmlEscaped(),
                         open.toHtmlEscaped());
    }
    return text + QStringLiteral("</table>");
}

QString BlockDocumentation::timingSection(const blocks::LoadedLibrary& library,
                                          const blocks::BlockDefinition& block,
                                          const blockdoc::TimingExample& example) {
    QString text = heading(tr("Timing diagram"));
    const blockdoc::TimingExampleFiles files = blockdoc::timingExampleFiles(library, block);
    if (!example.ran()) {
        text += QStringLiteral("<p><i>%1</i></p>")
                    .arg(tr("No timing diagram: %1")
                             .arg(QString::fromStdString(example.problem))
                             .toHtmlEscaped());
        return text;
    }
    text += QStringLiteral("<p><img src=\"%1\"></p>").arg(timingDiagramUrl().toString());
    const QString scenario =
        QDir::toNativeSeparators(QFileInfo(files.scenario).dir().dirName() + QLatin1Char('/') +
                                 QFileInfo(files.scenario).fileName());
    QString caption = tr("The pins of the example project %1 while its scenario %2 runs, from "
                         "power on.")
                          .arg(QFileInfo(files.project).fileName(), scenario);
    caption += QLatin1Char(' ');
    caption += example.failed == 0
                   ? tr("All %n expectation(s) of the scenario held.", nullptr, example.passed)
                   : tr("%n expectation(s) of the scenario failed: the diagram shows what the "
                        "block did, not what the example expects.",
                        nullptr, example.failed);
    text += QStringLiteral("<p><small>%1</small></p>").arg(caption.toHtmlEscaped());
    return text;
}

QString BlockDocumentation::statesTable(const blocks::BlockDefinition& block,
                                        const blockdoc::StateMachineTable& table) {
    QString text = heading(tr("States"));
    text += QStringLiteral("<p>%1</p>")
                .arg((table.diagCodeIsState
                          ? tr("DiagCode holds the state as its 16-bit pattern (16#8000 reads "
                               "-32768 in a register). The outputs each state switches on:")
                          : tr("The outputs each state switches on:"))
                         .toHtmlEscaped());
    text += QString::fromLatin1(kTable);
    text += QStringLiteral("<tr><th>%1</th><th>%2</th>").arg(tr("State"), tr("Meaning"));
    for (const std::string& output : table.outputs)
        text += QStringLiteral("<th>%1</th>").arg(escaped(output));
    text += QStringLiteral("</tr>");
    const std::string language = BlockText::descriptionLanguage();
    for (std::size_t i = 0; i < table.states.size(); ++i) {
        const int state = table.states[i];
        QString meaning;
        for (const blocks::StateMeaning& m : block.states)
            if (m.code == state)
                meaning = QString::fromStdString(m.meaning.in(language));
        text += QStringLiteral("<tr><td>%1</td><td>%2</td>")
                    .arg(code(blockdoc::stateCode(state)), meaning.toHtmlEscaped());
        for (std::size_t o = 0; o < table.outputs.size(); ++o)
            text += QStringLiteral("<td align=\"center\">%1</td>")
                        .arg(table.outputsOn[i][o] ? QStringLiteral("1") : QStringLiteral("0"));
        text += QStringLiteral("</tr>");
    }
    return text + QStringLiteral("</table>");
}

QString BlockDocumentation::transitionsTable(const blockdoc::StateMachineTable& table) {
    QString text = heading(tr("Transitions"));
    text += QStringLiteral("<p>%1</p>")
                .arg(tr("Each scan takes at most one transition: the first of the state's list "
                        "whose condition holds. The outputs then follow the new state. In the "
                        "conditions * is AND, + is OR and / is NOT, as in the program.")
                         .toHtmlEscaped());
    text += QString::fromLatin1(kTable);
    text += QStringLiteral("<tr><th>%1</th><th>%2</th><th>%3</th></tr>")
                .arg(tr("In state"), tr("Condition"), tr("Next state"));
    auto row = [&](const QString& from, const blockdoc::Transition& t) {
        return QStringLiteral("<tr><td>%1</td><td>%2</td><td>%3</td></tr>")
            .arg(from, t.condition.empty() ? tr("always").toHtmlEscaped() : code(t.condition),
                 code(blockdoc::stateCode(t.to)));
    };
    for (const blockdoc::Transition& t : table.transitions)
        if (t.from.empty())
            text += row(tr("any").toHtmlEscaped(), t);
    for (const int state : table.states) {
        bool first = true;
        for (const blockdoc::Transition* t : table.transitionsFrom(state)) {
            if (t->from.empty())
                continue;
            text += row(first ? code(blockdoc::stateCode(state)) : QString(), *t);
            first = false;
        }
    }
    text += QStringLiteral("</table>");
    if (!table.definitions.empty()) {
        text += QStringLiteral("<p>%1</p><ul>")
                    .arg(tr("The other lines of the block's body, which the conditions and outputs "
                            "use:")
                             .toHtmlEscaped());
        for (const blockdoc::Definition& d : table.definitions)
            text += QStringLiteral("<li>%1</li>")
                        .arg(code(d.name.empty() ? d.expression : d.name + " = " + d.expression));
        text += QStringLiteral("</ul>");
    }
    return text;
}

} // namespace rs::ui
