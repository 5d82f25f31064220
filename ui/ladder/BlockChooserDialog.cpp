// SPDX-License-Identifier: GPL-3.0-or-later
#include "BlockChooserDialog.h"

#include "BlockDocumentationDialog.h"
#include "BlockText.h"

#include <QDialogButtonBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QTextBrowser>
#include <QVBoxLayout>

namespace rs::ui {

BlockChooserDialog::BlockChooserDialog(const blocks::LibrarySet& libraries, QWidget* parent)
    : QDialog(parent), m_filter(new QLineEdit(this)), m_list(new QListWidget(this)),
      m_description(new QTextBrowser(this)) {
    setObjectName(QStringLiteral("blockChooserDialog"));
    setWindowTitle(tr("Insert Function Block"));
    for (const auto& library : libraries.libraries)
        for (const auto& block : library.library.blocks)
            m_blocks.emplace_back(&library, &block);
    m_filter->setObjectName(QStringLiteral("filter"));
    m_filter->setPlaceholderText(tr("Type to filter by name or description"));
    m_filter->setClearButtonEnabled(true);
    m_filter->installEventFilter(this);
    m_list->setObjectName(QStringLiteral("blocks"));
    m_description->setObjectName(QStringLiteral("description"));
    m_description->setOpenLinks(false);

    auto* filterLabel = new QLabel(tr("&Find:"), this);
    filterLabel->setBuddy(m_filter);
    auto* top = new QHBoxLayout;
    top->addWidget(filterLabel);
    top->addWidget(m_filter, 1);
    auto* middle = new QHBoxLayout;
    middle->addWidget(m_list, 2);
    middle->addWidget(m_description, 3);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    auto* documentation = buttons->addButton(tr("&Documentation..."), QDialogButtonBox::ActionRole);
    documentation->setObjectName(QStringLiteral("documentation"));
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(top);
    layout->addLayout(middle, 1);
    if (m_blocks.empty()) {
        auto* none = new QLabel(tr("The project's libraries hold no blocks. Add a library on the "
                                   "project page (Function libraries)."),
                                this);
        none->setWordWrap(true);
        layout->addWidget(none);
    }
    layout->addWidget(buttons);
    resize(720, 420);

    connect(m_filter, &QLineEdit::textChanged, this, &BlockChooserDialog::filter);
    connect(m_list, &QListWidget::currentRowChanged, this, &BlockChooserDialog::showChosen);
    connect(m_list, &QListWidget::itemActivated, this, &BlockChooserDialog::accept);
    connect(buttons, &QDialogButtonBox::accepted, this, &BlockChooserDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &BlockChooserDialog::reject);
    connect(documentation, &QPushButton::clicked, this, &BlockChooserDialog::showDocumentation);
    connect(m_description, &QTextBrowser::anchorClicked, this,
            &BlockChooserDialog::showDocumentation);
    auto enable = [this, buttons, documentation] {
        buttons->button(QDialogButtonBox::Ok)->setEnabled(block());
        documentation->setEnabled(block());
    };
    connect(m_list, &QListWidget::currentRowChanged, this, enable);
    filter();
    enable();
    m_filter->setFocus();
}

const blocks::LoadedLibrary* BlockChooserDialog::library() const {
    const QListWidgetItem* item = m_list->currentItem();
    return item && !item->isHidden() ? m_blocks[item->data(Qt::UserRole).toUInt()].first : nullptr;
}

const blocks::BlockDefinition* BlockChooserDialog::block() const {
    const QListWidgetItem* item = m_list->currentItem();
    return item && !item->isHidden() ? m_blocks[item->data(Qt::UserRole).toUInt()].second : nullptr;
}

void BlockChooserDialog::filter() {
    const QString wanted = m_filter->text().trimmed();
    m_list->clear();
    for (std::size_t i = 0; i < m_blocks.size(); ++i) {
        const auto& [library, block] = m_blocks[i];
        const QString name = QString::fromStdString(block->name);
        if (!wanted.isEmpty() && !name.contains(wanted, Qt::CaseInsensitive) &&
            !BlockText::description(*block).contains(wanted, Qt::CaseInsensitive))
            continue;
        auto* item = new QListWidgetItem(
            QStringLiteral("%1    (%2)").arg(name, QString::fromStdString(library->library.name)),
            m_list);
        item->setData(Qt::UserRole, static_cast<uint>(i));
        item->setToolTip(BlockText::description(*block));
    }
    m_list->setCurrentRow(m_list->count() > 0 ? 0 : -1);
    showChosen();
}

void BlockChooserDialog::showChosen() {
    const blocks::BlockDefinition* chosen = block();
    m_description->setHtml(chosen ? BlockText::html(*library(), *chosen) +
                                        QStringLiteral("<p><a href=\"documentation\">%1</a></p>")
                                            .arg(tr("The block's documentation: states, "
                                                    "transitions and a timing diagram")
                                                     .toHtmlEscaped())
                                  : QString());
}

void BlockChooserDialog::showDocumentation() {
    if (const blocks::BlockDefinition* chosen = block())
        BlockDocumentationDialog::show(*library(), *chosen, this);
}

// Up and Down in the filter move through the list, so the keyboard never
// has to leave the filter to choose.
bool BlockChooserDialog::eventFilter(QObject* watched, QEvent* event) {
    if (watched == m_filter && event->type() == QEvent::KeyPress) {
        const int key = static_cast<QKeyEvent*>(event)->key();
        if (key == Qt::Key_Down || key == Qt::Key_Up || key == Qt::Key_PageDown ||
            key == Qt::Key_PageUp) {
            QCoreApplication::sendEvent(m_list, event);
            return true;
        }
    }
    return QDialog::eventFilter(watched, event);
}

} // namespace rs::ui
