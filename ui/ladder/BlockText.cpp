// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockText.h"

#include <QLocale>

namespace rs::ui {

std::string BlockText::descriptionLanguage() {
    switch (QLocale().language()) {
    case QLocale::Swedish:
        return "sv";
    case QLocale::German:
        return "de";
    default:
        return "en";
    }
}

QString BlockText::description(const blocks::BlockDefinition& block) {
    return QString::fromStdString(block.description.in(descriptionLanguage()));
}

QString BlockText::pinSummary(const blocks::Pin& pin) {
    using blocks::PinKind;
    QStringList parts;
    const bool input = pin.direction == blocks::PinDirection::In;
    parts << (input ? tr("input") : tr("output"));
    switch (pin.kind) {
    case PinKind::Bit:
        parts << tr("bit");
        break;
    case PinKind::Register:
        parts << tr("register");
        break;
    case PinKind::DoubleRegister:
        parts << tr("double register");
        break;
    case PinKind::Time:
        parts << tr("time");
        break;
    case PinKind::Constant:
        parts << tr("constant");
        break;
    }
    if (input && pin.defaultValue)
        parts << tr("default %1").arg(QString::fromStdString(*pin.defaultValue));
    else if (input)
        parts << tr("must be bound");
    else if (pin.role == blocks::PinRole::Secondary)
        parts << tr("may stay open");
    return parts.join(QStringLiteral(", "));
}

QString BlockText::html(const blocks::LoadedLibrary& library,
                        const blocks::BlockDefinition& block) {
    QString text = QStringLiteral("<p><b>%1</b> &nbsp; %2</p>")
                       .arg(QString::fromStdString(block.name).toHtmlEscaped(),
                            tr("library %1, version %2")
                                .arg(QString::fromStdString(library.library.name),
                                     QString::fromStdString(block.version))
                                .toHtmlEscaped());
    if (block.kind == blocks::BlockKind::System)
        text += QStringLiteral("<p><i>%1</i></p>")
                    .arg(tr("A system block: the simulator carries out its instruction %1.")
                             .arg(QString::fromStdString(block.systemInstruction))
                             .toHtmlEscaped());
    text += QStringLiteral("<p>%1</p>").arg(description(block).toHtmlEscaped());
    text += QStringLiteral("<table cellspacing=\"0\" cellpadding=\"2\">");
    for (const auto& pin : block.pins)
        text += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(QString::fromStdString(pin.name).toHtmlEscaped(),
                         pinSummary(pin).toHtmlEscaped());
    text += QStringLiteral("</table>");
    return text;
}

} // namespace rs::ui
