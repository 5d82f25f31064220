// SPDX-License-Identifier: GPL-3.0-or-later
#include "pages/InstanceVariableText.h"

#include <QCoreApplication>

namespace rs::ui {

QString instanceVariableText(const blocks::InstanceVariable& variable) {
    const QString name = QString::fromStdString(variable.name);
    const QString block = QString::fromStdString(variable.blockType);
    if (variable.role == blocks::InstanceVariable::Role::Private)
        return QCoreApplication::translate("InstanceVariableText",
                                           "Private variable #%1 of block %2 (line %3)")
            .arg(name, block)
            .arg(variable.line);
    return QCoreApplication::translate("InstanceVariableText", "Pin %1 of block %2 (line %3)")
        .arg(name, block)
        .arg(variable.line);
}

std::map<lang::Address, QString>
instanceUseTexts(const std::vector<blocks::InstanceVariable>& variables) {
    std::map<lang::Address, QString> texts;
    for (const auto& variable : variables) {
        QString& text = texts[variable.address];
        if (!text.isEmpty())
            text += QLatin1Char('\n');
        text += instanceVariableText(variable);
    }
    return texts;
}

} // namespace rs::ui
