// SPDX-License-Identifier: GPL-3.0-or-later
#include "pl110/Pl110NamesPage.h"

#include "pl110/Address.h"
#include "pl110/NameCsv.h"
#include "pl110/Pl110Document.h"
#include "pl110/ScanEngine.h"
#include "project/ProjectFile.h"
#include "shell/StatusColors.h"

#include <QApplication>
#include <QDir>
#include <QFileDialog>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QSplitter>
#include <QTableWidget>
#include <QToolBar>
#include <QVBoxLayout>

namespace rs::ui {

namespace {

QString utf8(std::string_view text) {
    return QString::fromUtf8(text.data(), static_cast<qsizetype>(text.size()));
}

std::string trimmed(const QString& text) {
    return text.trimmed().toStdString();
}

// "I1–I256", "V0.0–V349.15, VW0–VW349, VD0–VD348".
QString addressRange(const pl110::AreaInfo& info) {
    QStringList ranges;
    if (!info.bitPrefix.empty()) {
        if (info.bitsOfWords)
            ranges << QStringLiteral("%1%2.0–%1%3.15")
                          .arg(utf8(info.bitPrefix))
                          .arg(info.first)
                          .arg(info.last);
        else
            ranges << QStringLiteral("%1%2–%1%3")
                          .arg(utf8(info.bitPrefix))
                          .arg(info.first)
                          .arg(info.last);
    }
    if (!info.wordPrefix.empty() && info.wordPrefix != info.bitPrefix)
        ranges << QStringLiteral("%1%2–%1%3")
                      .arg(utf8(info.wordPrefix))
                      .arg(info.first)
                      .arg(info.last);
    if (!info.doublePrefix.empty())
        ranges << QStringLiteral("%1%2–%1%3")
                      .arg(utf8(info.doublePrefix))
                      .arg(info.first)
                      .arg(info.last - 1);
    return ranges.join(QStringLiteral(", "));
}

QTableWidgetItem* readOnlyItem(const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

} // namespace

Pl110NamesPage::Pl110NamesPage(Pl110Document* document, QWidget* parent)
    : QWidget(parent), m_document(document), m_names(new QTableWidget(this)),
      m_areas(new QTableWidget(this)), m_problem(new QLabel(this)) {
    setObjectName(QStringLiteral("pl110NamesPage"));
    auto* toolBar = new QToolBar(this);
    toolBar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    QAction* import = toolBar->addAction(tr("&Import CSV..."));
    import->setObjectName(QStringLiteral("pl110ImportCsvAction"));
    import->setToolTip(tr("Name addresses from a CSV file: Variable, Symbolic Name, Description"));
    connect(import, &QAction::triggered, this, &Pl110NamesPage::chooseImport);
    QAction* exportAction = toolBar->addAction(tr("E&xport CSV..."));
    exportAction->setObjectName(QStringLiteral("pl110ExportCsvAction"));
    exportAction->setToolTip(tr("Write the names and descriptions to a CSV file"));
    connect(exportAction, &QAction::triggered, this, &Pl110NamesPage::chooseExport);

    m_names->setObjectName(QStringLiteral("pl110NamesTable"));
    m_names->setColumnCount(4);
    m_names->setHorizontalHeaderLabels({tr("Address"), tr("Name"), tr("Description"), tr("Value")});
    m_names->horizontalHeader()->setSectionResizeMode(DescriptionColumn, QHeaderView::Stretch);
    m_names->verticalHeader()->hide();
    m_names->setAlternatingRowColors(true);
    m_names->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed |
                             QAbstractItemView::AnyKeyPressed);
    connect(m_names, &QTableWidget::itemChanged, this, &Pl110NamesPage::edited);

    m_areas->setObjectName(QStringLiteral("pl110AreasTable"));
    m_areas->setColumnCount(4);
    m_areas->setHorizontalHeaderLabels(
        {tr("Addresses"), tr("Program writes"), tr("Modbus (word / bit)"), tr("What it holds")});
    m_areas->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
    m_areas->verticalHeader()->hide();
    m_areas->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_areas->setSelectionBehavior(QAbstractItemView::SelectRows);

    m_problem->setObjectName(QStringLiteral("pl110NamesProblem"));
    m_problem->setWordWrap(true);
    markAsError(m_problem);
    m_problem->hide();

    auto* namesLabel = new QLabel(tr("Names: double-click a cell to change it; the last row "
                                     "names another address."),
                                  this);
    namesLabel->setWordWrap(true);
    auto* areasLabel = new QLabel(tr("Memory areas of the PL110 (datasheet, section 2)"), this);
    auto* top = new QWidget(this);
    auto* topLayout = new QVBoxLayout(top);
    topLayout->setContentsMargins(0, 0, 0, 0);
    topLayout->addWidget(namesLabel);
    topLayout->addWidget(m_names, 1);
    topLayout->addWidget(m_problem);
    auto* bottom = new QWidget(this);
    auto* bottomLayout = new QVBoxLayout(bottom);
    bottomLayout->setContentsMargins(0, 0, 0, 0);
    bottomLayout->addWidget(areasLabel);
    bottomLayout->addWidget(m_areas, 1);
    auto* splitter = new QSplitter(Qt::Vertical, this);
    splitter->addWidget(top);
    splitter->addWidget(bottom);
    splitter->setStretchFactor(0, 3);
    splitter->setStretchFactor(1, 2);
    auto* layout = new QVBoxLayout(this);
    layout->addWidget(toolBar);
    layout->addWidget(splitter, 1);

    fillAreas();
    fillNames();
    connect(document, &Pl110Document::changed, this, &Pl110NamesPage::fillNames);
}

void Pl110NamesPage::fillAreas() {
    const auto table = pl110::areaTable();
    m_areas->setRowCount(static_cast<int>(table.size()));
    int row = 0;
    for (const pl110::AreaInfo& info : table) {
        m_areas->setItem(row, 0, readOnlyItem(addressRange(info)));
        m_areas->setItem(row, 1, readOnlyItem(info.programWrites ? tr("yes") : tr("no")));
        QString modbus = info.modbusWord < 0 ? tr("–") : QString::number(info.modbusWord);
        if (info.modbusBit >= 0)
            modbus += QStringLiteral(" / %1").arg(info.modbusBit);
        if (!info.modbusWrites && info.modbusWord >= 0)
            modbus += tr(" (read only)");
        m_areas->setItem(row, 2, readOnlyItem(modbus));
        m_areas->setItem(row, 3,
                         readOnlyItem(QCoreApplication::translate(
                             "rs::pl110::Area", std::string(info.description).c_str())));
        ++row;
    }
    m_areas->resizeColumnsToContents();
}

void Pl110NamesPage::fillNames() {
    m_filling = true;
    std::vector<const pl110::Line*> declared;
    for (const pl110::Line& line : m_document->program().declarations)
        if (std::holds_alternative<pl110::NameDeclaration>(line.body))
            declared.push_back(&line);
    m_names->setRowCount(static_cast<int>(declared.size()) + 1);
    m_addresses.clear();
    int row = 0;
    for (const pl110::Line* line : declared) {
        const auto& declaration = std::get<pl110::NameDeclaration>(line->body);
        m_addresses.push_back(declaration.variable.address);
        m_names->setItem(row, AddressColumn,
                         readOnlyItem(utf8(pl110::toString(declaration.variable.address))));
        m_names->setItem(row, NameColumn, new QTableWidgetItem(utf8(declaration.name)));
        m_names->setItem(row, DescriptionColumn,
                         new QTableWidgetItem(utf8(line->comment.value_or("")).trimmed()));
        m_names->setItem(row, ValueColumn, new QTableWidgetItem);
        ++row;
    }
    // The last row names another address.
    auto* address = new QTableWidgetItem;
    address->setToolTip(tr("Type an address such as I6, Q4, M10 or VW20"));
    m_names->setItem(row, AddressColumn, address);
    m_names->setItem(row, NameColumn, new QTableWidgetItem);
    m_names->setItem(row, DescriptionColumn, new QTableWidgetItem);
    m_names->setItem(row, ValueColumn, readOnlyItem({}));
    m_names->resizeColumnToContents(AddressColumn);
    m_names->resizeColumnToContents(NameColumn);
    m_filling = false;
}

void Pl110NamesPage::showValues(const pl110::ScanEngine* engine) {
    m_filling = true;
    m_live = engine != nullptr;
    // A value being typed is not overwritten by the next scan's.
    const QWidget* focus = QApplication::focusWidget();
    const bool editing = focus && m_names->viewport()->isAncestorOf(focus);
    for (int row = 0; row + 1 < m_names->rowCount(); ++row) {
        QTableWidgetItem* item = m_names->item(row, ValueColumn);
        if (editing && m_names->currentItem() == item)
            continue;
        item->setToolTip(engine ? tr("Type a value to set the input or force the variable")
                                : QString());
        if (!engine) {
            item->setText({});
            continue;
        }
        item->setText(QString::number(engine->value(m_addresses[static_cast<std::size_t>(row)])));
    }
    m_filling = false;
}

bool Pl110NamesPage::canRewrite(const QString& what) {
    if (m_document->readsWhole())
        return true;
    // Names change the text as the printer writes it; a line that does not
    // read would be lost.
    m_problem->setText(tr("%1 rewrites the program text; fix its errors on the Program page "
                          "first, so that no line is lost.")
                           .arg(what));
    m_problem->show();
    return false;
}

void Pl110NamesPage::edited(QTableWidgetItem* item) {
    if (m_filling)
        return;
    const int row = item->row();
    if (item->column() == ValueColumn) {
        enterValue(item);
        return;
    }
    const QString addressText = m_names->item(row, AddressColumn)->text().trimmed();
    const QString name = m_names->item(row, NameColumn)->text();
    const QString description = m_names->item(row, DescriptionColumn)->text();
    const bool lastRow = row == m_names->rowCount() - 1;
    if (lastRow && (addressText.isEmpty() || name.trimmed().isEmpty()))
        return; // the new row is complete when it has an address and a name
    m_problem->hide();
    if (!canRewrite(tr("Naming")))
        return;
    const pl110::AddressReading reading = pl110::readAddress(addressText.toStdString());
    if (reading.shape != pl110::AddressReading::Shape::Address) {
        m_problem->setText(reading.shape == pl110::AddressReading::Shape::Malformed
                               ? QString::fromStdString(reading.error)
                               : tr("“%1” is not a PL110 address").arg(addressText));
        m_problem->show();
        return;
    }
    pl110::Program program = m_document->program();
    bool changed = false;
    if (const auto why = pl110::nameAddress(program, reading.address, trimmed(name),
                                            trimmed(description), changed)) {
        m_problem->setText(QString::fromStdString(why->message));
        m_problem->show();
        return;
    }
    if (changed)
        m_document->setProgram(program, tr("Name %1").arg(utf8(pl110::toString(reading.address))));
}

void Pl110NamesPage::enterValue(QTableWidgetItem* item) {
    bool number = false;
    const qint64 value = item->text().trimmed().toLongLong(&number);
    if (!m_live || item->row() >= static_cast<int>(m_addresses.size())) {
        Q_EMIT message(tr("Start the simulation to set values."));
        return;
    }
    if (!number) {
        Q_EMIT message(tr("“%1” is not a whole number").arg(item->text()));
        return;
    }
    Q_EMIT valueEntered(m_addresses[static_cast<std::size_t>(item->row())], value);
}

void Pl110NamesPage::chooseImport() {
    const QString path = QFileDialog::getOpenFileName(this, tr("Import Names"),
                                                      QFileInfo(m_document->path()).absolutePath(),
                                                      tr("CSV files (*.csv *.txt);;All files (*)"));
    if (!path.isEmpty())
        importCsv(path);
}

void Pl110NamesPage::importCsv(const QString& path) {
    m_problem->hide();
    if (!canRewrite(tr("Importing names")))
        return;
    const project::FileText file = project::readTextFile(path);
    if (!file.error.isEmpty()) {
        m_problem->setText(file.error);
        m_problem->show();
        return;
    }
    const pl110::NameCsvImport import = pl110::importNamesCsv(m_document->program(), file.text);
    if (!import.problems.empty()) {
        // As the command line: a file with a bad row changes nothing.
        QStringList lines;
        for (const pl110::NameCsvProblem& problem : import.problems)
            lines << QStringLiteral("%1:%2:%3: %4")
                         .arg(QDir::toNativeSeparators(path))
                         .arg(problem.line)
                         .arg(problem.column)
                         .arg(QString::fromStdString(problem.message));
        m_problem->setText(tr("Nothing was imported: %n row(s) could not be read.\n%1", nullptr,
                              static_cast<int>(import.problems.size()))
                               .arg(lines.join(u'\n')));
        m_problem->show();
        return;
    }
    if (import.changed > 0)
        m_document->setProgram(import.program, tr("Import Names"));
    Q_EMIT message(tr("Imported %n name(s) from %1", nullptr, import.changed)
                       .arg(QDir::toNativeSeparators(path)));
}

void Pl110NamesPage::chooseExport() {
    const QString comma = tr("CSV, comma-separated (*.csv)");
    const QString semicolon = tr("CSV, semicolon-separated, as spreadsheets in Swedish and "
                                 "German expect (*.csv)");
    QString filter = comma;
    const QString suggested = m_document->path().isEmpty()
                                  ? QStringLiteral("names.csv")
                                  : QFileInfo(m_document->path()).path() + u'/' +
                                        QFileInfo(m_document->path()).completeBaseName() +
                                        QStringLiteral("-names.csv");
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export Names"), suggested, comma + QStringLiteral(";;") + semicolon, &filter);
    if (path.isEmpty())
        return;
    const QString error = exportCsv(path, filter == semicolon ? ';' : ',');
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export Names"), error);
    else
        Q_EMIT message(tr("Exported the names to %1").arg(QDir::toNativeSeparators(path)));
}

QString Pl110NamesPage::exportCsv(const QString& path, char separator) const {
    return project::writeTextFile(path, pl110::exportNamesCsv(m_document->program(), separator));
}

} // namespace rs::ui
