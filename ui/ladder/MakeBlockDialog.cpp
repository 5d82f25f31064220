// SPDX-License-Identifier: GPL-3.0-or-later
#include "MakeBlockDialog.h"

#include "BlockText.h"
#include "blocks/LibrarySearch.h"
#include "blocks/LibraryWords.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rs::ui {

MakeBlockDialog::MakeBlockDialog(std::vector<lang::Line> lines,
                                 std::set<lang::Address> usedElsewhere,
                                 const QStringList& libraryFiles, QWidget* parent)
    : QDialog(parent), m_lines(std::move(lines)), m_usedElsewhere(std::move(usedElsewhere)),
      m_name(new QLineEdit(QStringLiteral("NewBlock"), this)), m_library(new QComboBox(this)),
      m_description(new QLineEdit(this)), m_pins(new QTableWidget(this)),
      m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("makeBlockDialog"));
    setWindowTitle(tr("Make Block"));
    m_name->setObjectName(QStringLiteral("blockName"));
    m_library->setObjectName(QStringLiteral("library"));
    m_library->setEditable(true);
    m_library->addItems(libraryFiles);
    m_description->setObjectName(QStringLiteral("description"));
    m_description->setPlaceholderText(tr("What the block does, for its users"));
    m_pins->setObjectName(QStringLiteral("pins"));
    m_problem->setObjectName(QStringLiteral("problem"));
    m_problem->setWordWrap(true);
    m_problem->setStyleSheet(QStringLiteral("color: #c00000"));

    auto* form = new QFormLayout;
    form->addRow(tr("Block &name:"), m_name);
    form->addRow(tr("&Library file:"), m_library);
    form->addRow(tr("&Description:"), m_description);
    auto* explanation = new QLabel(
        tr("What the networks read becomes an input, what they write an output; a memory only "
           "they use becomes the block's own. Name the pins as the block's users will see "
           "them. Comments on the statements do not go into the block."),
        this);
    explanation->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(explanation);
    layout->addWidget(m_pins, 1);
    layout->addWidget(m_problem);
    layout->addWidget(buttons);
    resize(640, 460);
    connect(buttons, &QDialogButtonBox::accepted, this, &MakeBlockDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &MakeBlockDialog::reject);
    fillPins();
    m_name->setFocus();
    m_name->selectAll();
}

void MakeBlockDialog::fillPins() {
    m_draft = blocks::draftBlock("NewBlock", m_lines, m_usedElsewhere);
    m_pins->setColumnCount(3);
    m_pins->setHorizontalHeaderLabels(
        {tr("Name"), tr("Pin or private variable"), tr("Stands for")});
    m_pins->horizontalHeader()->setStretchLastSection(true);
    m_pins->verticalHeader()->hide();
    std::vector<std::pair<std::string, QString>> rows;
    for (const auto& pin : m_draft.block.pins)
        rows.emplace_back(pin.name, BlockText::pinSummary(pin));
    for (const auto& variable : m_draft.block.privates)
        rows.emplace_back(variable.name, tr("private memory"));
    m_pins->setRowCount(static_cast<int>(rows.size()));
    for (int row = 0; row < static_cast<int>(rows.size()); ++row) {
        const auto& [name, what] = rows[static_cast<std::size_t>(row)];
        m_pins->setItem(row, 0, new QTableWidgetItem(QString::fromStdString(name)));
        auto* kind = new QTableWidgetItem(what);
        kind->setFlags(kind->flags() & ~Qt::ItemIsEditable);
        m_pins->setItem(row, 1, kind);
        auto* address = new QTableWidgetItem(
            QString::fromStdString(lang::toString(m_draft.addresses.at(name))));
        address->setFlags(address->flags() & ~Qt::ItemIsEditable);
        address->setData(Qt::UserRole, QString::fromStdString(name));
        m_pins->setItem(row, 2, address);
    }
    m_pins->resizeColumnsToContents();
    if (!m_draft.refusal.empty())
        m_problem->setText(QString::fromStdString(m_draft.refusal));
}

QString MakeBlockDialog::libraryFile() const {
    QString file = m_library->currentText().trimmed();
    const QString extension = QStringLiteral(".") + QLatin1String(blocks::kLibraryExtension);
    if (!file.endsWith(extension))
        file += extension;
    return file;
}

std::string MakeBlockDialog::newLibraryName() const {
    return QFileInfo(libraryFile()).completeBaseName().toStdString();
}

void MakeBlockDialog::accept() {
    // The names as typed, for what the draft named them after.
    std::map<lang::Address, std::string> names;
    const auto drafted = m_draft.addresses;
    for (int row = 0; row < m_pins->rowCount(); ++row) {
        const std::string was = m_pins->item(row, 2)->data(Qt::UserRole).toString().toStdString();
        names[drafted.at(was)] = m_pins->item(row, 0)->text().trimmed().toStdString();
    }
    blocks::BlockDraft draft =
        blocks::draftBlock(m_name->text().trimmed().toStdString(), m_lines, m_usedElsewhere, names);
    if (draft.refusal.empty() && (QFileInfo(libraryFile()).fileName() != libraryFile() ||
                                  !blocks::isLibraryName(newLibraryName())))
        draft.refusal = tr("The library file is a name of letters, digits and '_' in the "
                           "project's folder, such as My_Blocks.rslib.")
                            .toStdString();
    if (!draft.refusal.empty()) {
        m_problem->setText(QString::fromStdString(draft.refusal));
        return;
    }
    draft.block.version = "1.0";
    draft.block.description.english = m_description->text().trimmed().toStdString();
    if (draft.block.description.english.empty())
        draft.block.description.english = "Made from networks with Make Block.";
    m_draft = std::move(draft);
    QDialog::accept();
}

} // namespace rs::ui
