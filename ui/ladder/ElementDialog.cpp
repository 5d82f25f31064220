// SPDX-License-Identifier: GPL-3.0-or-later
#include "ElementDialog.h"

#include "document/ProjectDocument.h"
#include "ladder/ElementText.h"
#include "ladder/SymbolTable.h"
#include "project/VariableTable.h"
#include "shell/CompleterKeys.h"
#include "shell/DialogProblem.h"

#include <QCheckBox>
#include <QComboBox>
#include <QCompleter>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QStringListModel>
#include <QVBoxLayout>

namespace rs::ui {

ElementDialog::ElementDialog(ProjectDocument* document, int station, bool output,
                             const ElementFields& fields, QWidget* parent)
    : QDialog(parent), m_document(document), m_station(station), m_isOutput(output),
      m_kind(new QComboBox(this)), m_operandLabel(new QLabel(this)), m_operand(new QLineEdit(this)),
      m_valueLabel(new QLabel(tr("Value:"), this)), m_value(new QLineEdit(this)),
      m_negated(new QCheckBox(tr("&Negated (passes power when false)"), this)),
      m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("elementDialog"));
    setWindowTitle(output ? tr("Output Properties") : tr("Element Properties"));
    m_kind->setObjectName(QStringLiteral("kind"));
    m_operand->setObjectName(QStringLiteral("operand"));
    m_value->setObjectName(QStringLiteral("value"));
    m_value->setPlaceholderText(tr("such as >= 5, = R0.2, += 2, ++"));
    m_negated->setObjectName(QStringLiteral("negated"));
    for (const ElementKindInfo& info : ladder::elementKinds())
        if (info.output == output)
            m_kind->addItem(ElementKinds::name(info.kind), static_cast<int>(info.kind));
    m_kind->setCurrentIndex(m_kind->findData(static_cast<int>(fields.kind)));
    m_operand->setText(QString::fromStdString(fields.operand));
    m_value->setText(QString::fromStdString(fields.value));
    m_negated->setChecked(fields.negated);

    auto* form = new QFormLayout;
    form->addRow(tr("&Type:"), m_kind);
    m_newVariable = new QPushButton(tr("New &Variable..."), this);
    m_newVariable->setObjectName(QStringLiteral("newVariable"));
    // Alt+V opens it; Tab passes it by, so a space typed after Tab from the
    // operand does not open a dialog (issue 17).
    m_newVariable->setFocusPolicy(Qt::ClickFocus);
    m_newVariable->setAutoDefault(false);
    auto* operandRow = new QHBoxLayout;
    operandRow->addWidget(m_operand, 1);
    operandRow->addWidget(m_newVariable);
    form->addRow(m_operandLabel, operandRow);
    form->addRow(m_valueLabel, m_value);
    form->addRow(QString(), m_negated);
    if (output) {
        m_comment = new QLineEdit(QString::fromStdString(fields.comment), this);
        m_comment->setObjectName(QStringLiteral("comment"));
        form->addRow(tr("&Comment:"), m_comment);
    }
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->hide();
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);

    auto* completer = new QCompleter(new QStringListModel(this), this);
    completer->setCaseSensitivity(Qt::CaseInsensitive);
    completer->setFilterMode(Qt::MatchContains);
    m_operand->setCompleter(completer);
    finishCompletionInOneKey(completer);
    fillCompletion();

    connect(buttons, &QDialogButtonBox::accepted, this, &ElementDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &ElementDialog::reject);
    connect(m_kind, &QComboBox::currentIndexChanged, this, &ElementDialog::kindChanged);
    connect(m_newVariable, &QPushButton::clicked, this, &ElementDialog::newVariable);
    kindChanged();
    m_operand->setFocus();
    m_operand->selectAll();
}

void ElementDialog::fillCompletion() {
    if (!m_document)
        return;
    QStringList words;
    const project::Project& project = m_document->project();
    for (const lang::Address& address : project::namedAddresses(project, m_station)) {
        const std::string name = project::variableName(project, address);
        words << QString::fromStdString(name);
    }
    words.removeDuplicates();
    words.sort(Qt::CaseInsensitive);
    static_cast<QStringListModel*>(m_operand->completer()->model())->setStringList(words);
}

void ElementDialog::kindChanged() {
    const auto kind = static_cast<ElementKind>(m_kind->currentData().toInt());
    m_operandLabel->setText(ElementKinds::operandLabel(kind));
    const ElementKindInfo& info = ladder::infoOf(kind);
    m_valueLabel->setVisible(info.hasValue);
    m_value->setVisible(info.hasValue);
    m_negated->setVisible(info.canNegate);
    // A jump's step and a sequence reset's sequence are no variables.
    m_newVariable->setVisible(info.operandRole != ladder::OperandRole::Step &&
                              info.operandRole != ladder::OperandRole::Sequence);
    m_problem->clear();
}

void ElementDialog::newVariable() {
    if (!m_document)
        return;
    QDialog dialog(this);
    dialog.setObjectName(QStringLiteral("newVariableDialog"));
    dialog.setWindowTitle(tr("New Variable"));
    auto* address = new QLineEdit(&dialog);
    address->setObjectName(QStringLiteral("address"));
    auto* name = new QLineEdit(&dialog);
    name->setObjectName(QStringLiteral("name"));
    const lang::AddressWord typed =
        lang::readAddressWord(m_operand->text().trimmed().toStdString());
    if (typed.shape == lang::AddressWord::Shape::Variable)
        address->setText(QString::fromStdString(lang::toString(typed.address)));
    else
        name->setText(m_operand->text().trimmed());
    auto* problem = new QLabel(&dialog);
    problem->setObjectName(QStringLiteral("problem"));
    problem->setWordWrap(true);
    problem->hide();
    auto* form = new QFormLayout(&dialog);
    form->addRow(tr("&Address:"), address);
    form->addRow(tr("Symbolic &name:"), name);
    form->addRow(problem);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, [&] {
        const lang::AddressWord word =
            lang::readAddressWord(address->text().trimmed().toStdString());
        if (word.shape != lang::AddressWord::Shape::Variable) {
            sayProblem(problem,
                       tr("Write an address such as I%1.0, Q%1.2 or M%1.5.").arg(m_station));
            return;
        }
        const std::string text = name->text().trimmed().toStdString();
        if (text.empty()) {
            sayProblem(problem, tr("Give the variable a name."));
            return;
        }
        if (auto refusal = project::checkVariableName(m_document->project(), word.address, text)) {
            sayProblem(problem, QString::fromStdString(*refusal));
            return;
        }
        m_document->edit(
            tr("Name %1 %2")
                .arg(QString::fromStdString(lang::toString(word.address)),
                     QString::fromStdString(text)),
            [&](project::Project& p) { project::setVariableName(p, word.address, text); });
        dialog.accept();
    });
    if (dialog.exec() != QDialog::Accepted)
        return;
    fillCompletion();
    m_operand->setText(name->text().trimmed());
}

void ElementDialog::accept() {
    if (!m_document)
        return QDialog::reject();
    const auto kind = static_cast<ElementKind>(m_kind->currentData().toInt());
    ladder::ElementFields fields;
    fields.kind = kind;
    fields.operand = m_operand->text().toStdString();
    fields.value = m_value->text().toStdString();
    fields.negated = m_negated->isChecked();
    const ladder::FieldsText made = ladder::textOf(fields);
    if (made.text.empty()) {
        sayProblem(m_problem, QString::fromStdString(made.error));
        return;
    }
    const QString text = QString::fromStdString(made.text);
    const lang::Document& program = m_document->project().program;
    if (m_isOutput) {
        ladder::OutputReading read = ladder::readOutput(program, m_station, text.toStdString());
        if (!read.output) {
            sayProblem(m_problem, tr("%1: %2").arg(text, QString::fromStdString(read.error)));
            return;
        }
        const QString comment = m_comment->text().trimmed();
        if (!comment.isEmpty())
            read.output->comment = " " + comment.toStdString();
        m_output = std::move(read.output);
    } else {
        ladder::ElementReading read = ladder::readElement(program, m_station, text.toStdString());
        if (!read.element) {
            sayProblem(m_problem, tr("%1: %2").arg(text, QString::fromStdString(read.error)));
            return;
        }
        m_element = std::move(read.element);
    }
    QDialog::accept();
}

} // namespace rs::ui
