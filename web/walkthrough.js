// The thesis's Appendix C session as the page's guided demo: the worked line of docs/thesis.md
// (scripts/thesis/line_q1_worked.alp): Z = 12, from (0100, 0050) to (0300, 0200) in steps of
// 0.05 mm, 750 mm/min. Each step: what to do, the keys, and the display that follows.
export const WALKTHROUGH = [
  { say: 'RESET: the monitor signs on.', keys: ['RESET'], wait: '-ALP 85-' },
  { say: 'Start the thesis program at 0800H with the monitor’s R 7 command; it asks for Z.', keys: ['R', '7', '0', '8', '0', '0', 'EXEC'], wait: '?.=----' },
  { say: 'Z = 0012: the Z table moves 12 steps (4 ms each), then X1 is asked.', keys: ['0', '0', '1', '2'], wait: 'H1=----' },
  { say: 'X1 = 0100, EXEC.', keys: ['0', '1', '0', '0', 'EXEC'], wait: 'y1=----' },
  { say: 'Y1 = 0050, EXEC.', keys: ['0', '0', '5', '0', 'EXEC'], wait: 'H2=----' },
  { say: 'X2 = 0300, EXEC.', keys: ['0', '3', '0', '0', 'EXEC'], wait: 'y2=----' },
  { say: 'Y2 = 0200, EXEC.', keys: ['0', '2', '0', '0', 'EXEC'], wait: 'H=----' },
  { say: 'Feed 0750 mm/min; EXEC starts the line, and “Bitti” (done) ends it: 200 X and 150 Y steps.', keys: ['0', '7', '5', '0', 'EXEC'], wait: '  8itti' },
];
