// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "AsiOptions.h"
#include "Baseline.h"
#include "ExternalComm.h"
#include "Gateway.h"
#include "Protection.h"
#include "lang/Ast.h"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace rs::project {

// A whole project: the program text as a syntax tree (units, declarations,
// code, comments) plus what the language has no words for. The file format
// (docs/file-format.md) keeps the latter in structured comments.
struct Project {
    lang::Document program;
    std::string description;
    bool includeSource = false;
    std::map<int, std::string> unitDescriptions; // by station
    // Units whose identifier circuit is an IDFIX-PROG (manual Part 1, 5.1).
    std::set<int> idfixProg;
    // The AS-i Options page of the AS-i units that differ from the defaults
    // (manual Part 1, 7.1), by station.
    std::map<int, AsiOptions> asiOptions;
    // The gateways on the project's bus, by node address 0-15 (Gateway.h).
    std::map<int, Gateway> gateways;
    // A CAN bus cycle time other than the default (Part 1, 5.2), in ms, by station.
    std::map<int, int> canCycleMs;
    // The External communication setting of the units that receive gateway
    // data (Part 1, 5.3; ExternalComm.h), by station.
    std::map<int, ExternalComm> externalComm;
    std::map<lang::Address, std::string> variableDescriptions; // by address
    // The manual's [E]: local variables made visible to the other units (10.2.1).
    std::set<lang::Address> exportedVariables;
    // The manual's [R]: registers and memories kept at power off (10.3).
    std::set<lang::Address> remanentVariables;
    // The function libraries the project uses (manual Part 1, 12.1): a
    // standard library by its name, a user library by its file, relative to
    // the project's folder. None named: every library found is used
    // (docs/block-libraries.md).
    std::vector<std::string> libraries;
    // The version last marked as validated, if any (Baseline.h).
    std::optional<Baseline> baseline;
    // Password protection, if any (Protection.h).
    std::optional<Protection> protection;

    // The project name from "$name", empty when the file has none.
    std::string name() const;

    // Stations that have an id_pluto declaration or code, in ascending order.
    std::vector<int> stations() const;

    friend bool operator==(const Project&, const Project&) = default;
};

// One network of a step: statements shown together, with a comment. In a file
// written by hand each statement is its own network; ";@network" lines group.
struct Network {
    std::string comment;
    std::vector<const lang::Line*> lines; // statements, comments and blank lines in order
};

std::vector<Network> networksOf(const lang::Step& step);

} // namespace rs::project
