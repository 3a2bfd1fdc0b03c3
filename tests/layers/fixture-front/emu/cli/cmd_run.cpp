// alp85 run as it was before it made the Session's typed calls: Commands built and executed. Refused.
std::vector<Command> commands;
commands.push_back(command(Op::Reset));
if (errors.empty()) session.check(commands, errors);
const auto o = session.execute(c);
report << session.machine().cpu().regs().pc;
