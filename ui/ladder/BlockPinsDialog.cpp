// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockPinsDialog.h"

#include "BlockDocumentationDialog.h"
#include "BlockText.h"
#include "blocks/InstanceStanding.h"
#include "document/ProjectDocument.h"
#include "project/VariableTable.h"
#include "shell/CompleterKeys.h"

#include <QCompleter>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStringListModel>
#include <QVBoxLayout>

namespace rs::ui {

BlockPinsDialog::BlockPinsDialog(ProjectDocument* document, int station,
                                 const blocks::BlockDefinition& block,
                                 const blocks::BlockInstance& instance, QWidget* parent)
    : QDialog(parent), m_document(document), m_station(station), m_block(block),
      m_instance(instance), m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("blockPinsDialog"));
    setWindowTitle(tr("%1 Pins").arg(QString::fromStdString(block.name)));

    QStringList names;
    if (document) {
        const project::Project& project = document->project();
        for (const lang::Address& address : project::namedAddresses(project, station))
            names << QString::fromStdString(project::variableName(project, address));
        names.removeDuplicates();
        names.sort(Qt::CaseInsensitive);
    }
    auto* model = new QStringListModel(names, this);

    auto* description = new QLabel(BlockText::description(block), this);
    description->setWordWrap(true);
    auto* form = new QFormLayout;
    for (const auto& pin : block.pins) {
        auto* field = new QLineEdit(this);
        field->setObjectName(QStringLiteral("pin_") + QString::fromStdString(pin.name));
        if (const blocks::Binding* bound = instance.findPin(pin.name))
            field->setText(QString::fromStdString(bound->operand));
        field->setPlaceholderText(pin.defaultValue ? QString::fromStdString(*pin.defaultValue)
                                                   : QStringLiteral("???"));
        field->setToolTip(BlockText::pinSummary(pin));
        auto* completer = new QCompleter(model, field);
        completer->setCaseSensitivity(Qt::CaseInsensitive);
        completer->setFilterMode(Qt::MatchContains);
        field->setCompleter(completer);
        finishCompletionInOneKey(completer);
        auto* label = new QLabel(QStringLiteral("%1 <small>(%2)</small>:")
                                     .arg(QString::fromStdString(pin.name).toHtmlEscaped(),
                                          BlockText::pinSummary(pin).toHtmlEscaped()),
                                 this);
        label->setBuddy(field);
        form->addRow(label, field);
        m_fields.push_back(field);
    }
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c00000"));
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    if (document && blocks::libraryOf(instance, document->libraries())) {
        auto* documentation =
            buttons->addButton(tr("&Documentation..."), QDialogButtonBox::ActionRole);
        documentation->setObjectName(QStringLiteral("documentation"));
        connect(documentation, &QPushButton::clicked, this, [this] {
            if (const blocks::LoadedLibrary* library =
                    blocks::libraryOf(m_instance, m_document->libraries()))
                BlockDocumentationDialog::show(*library, m_block, this);
        });
    }
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(description);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &BlockPinsDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &BlockPinsDialog::reject);
    if (!m_fields.empty())
        m_fields.front()->setFocus();
}

void BlockPinsDialog::accept() {
    blocks::BlockInstance bound = m_instance;
    bound.pins.clear();
    for (std::size_t i = 0; i < m_block.pins.size(); ++i) {
        const QString operand = m_fields[i]->text().trimmed();
        if (!operand.isEmpty())
            bound.pins.push_back({m_block.pins[i].name, operand.toStdString(), 0});
    }
    // A pin now bound no longer needs the variable that stood in for it.
    std::erase_if(bound.privates, [&](const blocks::Binding& variable) {
        const auto dot = variable.name.find('.');
        return variable.name.starts_with("pin.") && dot != std::string::npos &&
               bound.findPin(variable.name.substr(dot + 1));
    });
    if (m_document) {
        const lang::Diagnostics problems =
            blocks::callProblems(m_document->project().program, m_station, m_block, bound);
        if (lang::errorCount(problems) > 0) {
            QStringList lines;
            for (const auto& problem : problems)
                lines << QString::fromStdString(problem.message);
            m_problem->setText(lines.join(u'\n'));
            return;
        }
    }
    m_result = std::move(bound);
    QDialog::accept();
}

} // namespace rs::ui
