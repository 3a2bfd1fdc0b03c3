#!/usr/bin/env python3
"""Writes the line table of RECONSTRUCTION.md (stdout) from thesis.asm and the OCR rows.

The OCR column: ocr_rows.py's automatic split of the seed's two-column rows, replaced by a hand
reading where rows are merged or unnumbered (OVERRIDE below). The statement column: the line of
thesis.asm tagged "; Lnnn" outside an IF FIXED branch (the printed build). Changes and reasons:
REASON below; a line is "printed" when its OCR text, with the usual confusions undone, equals the
statement."""
import json, re, sys
asm = open(sys.argv[1]).read().split('\n')
ocr = {int(k): v[0] for k, v in json.load(open(sys.argv[2])).items()}
O = {}
def o(n, t): O[n] = t
for n, t in [(26,'LHLD 1803H'),(27,'SHLD 1832H'),(28,'CALL YID'),(29,'LOOP : CALL OKEY'),(30,'12. SOBE'),(31,'CALL OUT'),
  (45,'COMP'),(67,'ACHE POP GOV B'),(68,'(row 58) COMP : DCX H'),(69,'DCX H'),(70,'NOV A,H'),(71,'CNA'),(72,'ADI 01H'),
  (73,'VON A,A'),(75,'VOK A,K'),(76,'AKO'),(83,'(row 93) 081 80H'),(84,'(row 94) VOM M,A'),(87,'CALL SS'),(88,'LXI H,1BOFH'),
  (134,'ING CONT'),(136,'CONT : DCR B'),(137,'JNZ STAR (on row 136)'),(138,'(row 137) LDA 1B4BH'),(139,'(unnumbered row) ORA C'),
  (140,'(row 139) STA 1B4BH'),(141,'(row 140) RET'),(142,'(row 141) MÖV A,M; (row "142 SHIFT : 143") SHIFT :'),(143,'—'),
  (144,'—'),(145,'—'),(146,'—'),(147,'SHIFT1: na n Nov A,M'),(148,'—'),(149,'—'),(150,'—'),(151,'SHIFT 2 : MOV A,M'),(152,'RAL'),
  (175,'RET'),(176,'(row 175) REPEAT : LHLD 1B42H'),(180,'RET'),(181,'—'),(182,'END OF MULT'),(183,'—'),(184,'(row 183) DIVI SUBROUTINE'),
  (185,'(row 1857) TIAL SODUMITUR'),(186,'DIVI : LHLD 1B18H'),(187,'XCHG'),(188,'LHLD 1B1CH'),(189,'—'),(190,'MOV B,H'),
  (191,'LXI H,0000H'),(192,'CALL DIV'),(193,'XCHG'),(194,'SHLD 182AH'),(195,'LHLD 1B1CH'),(196,'—'),(197,'MOV B,H'),(198,'='),
  (199,'XCHG'),(200,'CALL DIV'),(282,'SHOWYZ: CALLY'),(283,'CALL ONLE2'),(284,'CALL YY12 (on row 283)'),(285,'(row 284) CALL CEVIR'),
  (286,'(row 285) SHLD 1809H'),(288,'(row "288 289") JZ BASLA'),(289,'—'),(292,'(unnumbered row) SIFIR: CALL ANWAZL'),(296,'—'),
  (297,'(row 270) X; MVI A,76H'),(298,'A.'),(300,'Y: MVI A, 6EH')]: o(n, t)
left = ['HOB, A IVM','LHLD 1809H','LHLD 1B09H','SHLD 1BOFH.','SUB A','STA IBIIH','LDA 1814H','LDA 1B14H','STA 1839H','LHLD 1812H',
  'SHLD 1818H','LHLD IBOOH','SHLD 1BOCH','MVI A,80H','STA 1BOEH','LHLD 1806H','SHLD 1BOFH','—','STA 1B11H','CALL ADDSUB','—',
  'LXI H,1B3AH','—','—','—','MOV M,A','LHLD 1B12H','—','LHLD 1B18H','DAD D','SHLD 1B2EH','LHLD 1B18H .','SHLD 1B50H','LHLD 181CH',
  'SHLD 1852H','CALL DIVI','LHLD 1828','SHLD 1B40H','LHLD 182AH','SHLD 1B42H','LX1 H,0000H','SHLD 1846H','LHLD 1BOOH','SHLD 1844H',
  'CALL MULT','LHLD 184AH','SHLD IBOCH','LDA 1B39H','XRI 80H','STA 180EH']
for i, t in enumerate(left): o(501 + i, t + (' (unnumbered row)' if i < 14 or i == 19 else ''))
for n, t in [(551,'LHLD 1B03H'),(552,'—'),(553,'SUB A'),(554,'—'),(555,'CALL ADDSUB'),(556,'LHLD 1812H'),(557,'SHLD 1BOCH'),
  (558,'LDA 1814H'),(559,'STA 160EH'),(560,'LHLD 1B40H'),(561,'SHLD 1B4CH'),(562,'LHLD 1842H'),(563,'SHLD 1B4EH'),(564,'RET'),
  (565,', , , , ,'),(566,':END OF PARAM'),(567,';'),(568,'; YID SUBROUTINE'),(569,','),(570,'YID: —'),(571,'(row "57 i") SHLD 1844H'),
  (572,'LX1 H,0000H'),(573,'SHLD 1846H'),(574,'CALL MULT'),(600,'RET (last row of the page; 601 RET heads the next)'),(601,'RET'),(602,', pur or plant'),
  (603,': END OF BITTI'),(604,', auby aupholiming'),(605,': OKEY SUBROUTINE'),(606,', , , , ,'),(607,'OKEY:LDA 1B06 H'),
  (608,'LXI H, 1B34 H (printed twice, second time as row 808)'),(638,'(unnumbered row) STA 1B54H'),(639,'(row 638) ANA A'),
  (640,'(row 639) JZ 000'),(641,'CPI 01H'),(642,'JZ 001'),(643,'CPI 02H'),(644,'12 002'),(645,'003: CALL COMPAR'),(646,'JNZ 031'),
  (647,'032: HVI A,00H'),(648,'OUT OF9H'),(649,'MVI A,01H'),(650,'MOV E,A'),(651,'CALL DELAY (page header reads "OUT STATEMENT OF9H")'),
  (652,'CALL INPUT'),(653,'RET INFOI'),(654,'0011 NVI A,08H'),(655,'(unnumbered row) 031: OUT n,00n 0F9H'),(656,'IVM A,OCH'),
  (657,'VOK E,A 0F9H (row 65B)'),(658,'OUT (row "658 750")'),(659,'CALL DELAM'),(660,'CALL INPUT INLOI'),(661,'006. RET COMBAD'),
  (662,'000: CALL COMPAR'),(663,'000: JNZ 041'),(664,'042: NVI A,02H'),(690,'011: IVK A,00H'),(691,'0111 OUT 0F9H'),(692,'MAI A,04H'),
  (700,'022: IVM A,00H'),(701,'OUT 0F9H'),(702,'IVM A,01H'),(703,'YOM'),(704,'OUT OF9H'),(705,'CALL'),(706,'CALL INPUT'),(707,'RET'),
  (708,'70B 021: IVM A,08H'),(709,'TUO'),(710,'MAI A,OCH'),(725,'DELAY: 1B38H'),(741,'; ;END O ...'),(742,'r oot'),(743,'; . DEDUT'),
  (744,': INPUT ... UIING'),(745,'3 7'),(746,'INPUT: —'),(749,'CP I 08H'),(750,'12 YDEC'),(751,'(row "LIN YINCE ;") LHLD 1B32H'),
  (752,'TINUE , INX H'),(753,'SHLD nzegt (1832H)'),(754,'RET'),(755,'YDEC: LHLD 1B32H'),(759,'STEST: CP1 01H'),(763,'XINCE LHLD 1B34H'),
  (783,'—'),(784,':END OF INPUT'),(785,'—'),(786,'ANA: LDA 1B03H'),(805,'JZ SOEEN'),(806,'NVI A,00H . (unnumbered row)'),
  (807,'(row 806) 0F9H; (row 807) TUO'),(808,'MVI A,04H'),(809,'TUO OF9H'),(843,'XCHG (Cyrillic letters)'),(844,'(row B44 .) 1B18H'),
  (845,'CALL DIVI'),(846,'CBOL1: LDA 1B29H'),(847,'CPI 80H'),(848,'ŔĊ'),(849,'CP1 0C8H'),(850,'JNC BB0L2'),(851,'LDA 1839H'),
  (852,'MOV B,A'),(853,'ANA A,'),(854,'RAR'),(855,'ANA A'),(856,'RAR'),(857,'ANA A'),(858,'RAR'),(859,'VOM C,A'),
  (860,'(unnumbered row) ANA A A'),(861,'(row 860) RAR'),(862,'(row 861) C'),(863,'(row 862) ADD'),(864,'ADD B (row 863)'),
  (865,'(row 854) STA 1B38H'),(866,'RET'),(867,'BBOL2: CP1 H830 (row 866)'),(868,'JNC BBOL3 (row 867)')]: o(n, t)
# printed rows from 866 on are shifted by one in the OCR: fix the rest by hand
for n, t in [(866,'BBOL2: CP1 H830'),(867,'JNC BBOL3'),(868,'LDA 1B38H (row 898)'),(869,'VOK B,A'),(870,'ANA A'),(871,'RAR'),
  (872,'ANA A'),(873,'RAR'),(874,'ADD'),(875,'STA 1838H'),(876,'RET'),(877,'BBOL3: LDA 1838H'),(878,'YOM B,A'),(879,'ANA A'),
  (880,'rar'),(881,'YOH C,A'),(882,'ANA A'),(883,'RAR'),(884,'ADD C'),(885,'ADD B'),(886,'STA 1B38H'),(887,'RET'),(888,'END'),
  (864,'STA 1B38H (row 854)'),(865,'RET')]: o(n, t)
for n in (862, 863): pass
o(862, 'ADD C (row 861 "C", row 862 "ADD")'); o(863, 'ADD B (row 863)')
REASON = {}
def r(ns, t):
    for n in ns: REASON[n] = t
# reasons for the lines that needed more than undoing the usual confusions
r([10], 'E0B0H is no RAM address; 2 read as E: 20B0H in the 8155 RAM (docs/board.md)')
r([11], 'FIH: I read as 1 -> 0F1H (8279 command "end interrupt"); see open question Q4')
r([18], 'JZ printed "12"; SPEED1 is on the lost pages (reconstructed there)')
r([28, 29], 'LOOP printed at line 29 (YID outside the loop): erratum E4, moved to 28 in thesis-fixed')
r([45, 49], 'mnemonic lost; CNZ: only a negative operand is complemented (ANI 80H before it)')
r([62], 'mnemonic lost; JZ: a positive sum skips the conversion')
r([67], 'POP B; no RET follows: ADDSUB runs on into COMP (harmless, see Notes)')
r([95], 'printed MOV M,A (operands as printed): erratum E2, MOV A,M in thesis-fixed')
r([134], 'ING = JNC (the multiplier bit shifted out)')
r([136, 137], 'two statements on one row')
r(range(138, 143), 'rows shifted by one after the merged row 136/137')
r([143], 'lost; ANA A clears CY so the 32-bit shift starts with 0')
r([144, 145, 146, 148, 149, 150], 'lost; the pattern of SHIFT1/SHIFT2 (MOV A,M / RAL / MOV M,A / INX H)')
r(range(181, 186), 'comment rows; numbers garbled')
r([189, 196], 'lost; BC = divisor needs MOV C,L before MOV B,H')
r([198], 'printed "="; DE must be 0 and HL the remainder for the fraction: LXI H,0000H then XCHG')
r([206, 207, 208, 209], 'lost; BC = -divisor (two\'s complement of BC: CMA on both bytes, then INX B at 210)')
r([214], 'printed 09H; only 8 makes the 8-bit loop divide (uncertain: 8/9 confusion, see Q7)')
r([227, 228], 'lost; end of the byte when the last bit did not fit (CY = last quotient bit 0)')
r([230, 231, 232, 233, 234], 'lost; the bit fitted: drop the saved remainder, quotient bit 1, count, next bit')
r([238, 239, 240, 241, 242, 243, 244], 'lost; remainder overflowed 16 bits: it fits for sure (ADC A set the bit)')
r([245], 'printed "MEI": RET')
r([252], '"2" read as Z (the Z axis routine at 295)')
r([255], 'XX122: the doubled 2 of XX12 (the same routine at 274)')
r([264, 283], 'ONLE1/ONLE2 as printed (display "1"/"2" after y)')
r([266], 'CEVIRI: I read as 1')
r([279], 'lost; MOV A,E as at 260 and 269')
r([282], 'SHOWYZ: Z read as 2 (the Y2 entry); CALLY = CALL Y')
r([285], 'CEVIR as printed (no LXI H,0 before it: CEVIR clears HL itself, see Q5)')
r([286], 'rows 282-286 shifted; COORD ends without an F test for Y2 (erratum E15)')
r([289], 'lost; NOP (no effect; see Q1)')
r([296], 'lost; Z must not run on into X (8 digits would not hold "?HH1=----"): JMP to the Z entry')
r([298], 'lost; CALL AUS (X shows its letter)')
r([301, 302], 'lost page; CALL AUS / RET as X')
r([499, 500], 'lost page; PARAM\'s start, the pattern of 512-520 for Y')
r([501], 'printed reversed "HOB, A IVM" = MVI A,80H')
r([502], 'printed as a copy of 503; STA 1B0EH as at 515 (operand 1 = -Y1)')
r([507], 'printed as a copy of 508; CALL ADDSUB as at 520 (Y2 - Y1)')
r([518], 'lost; SUB A as at 505 (operand 2 positive)')
r([521], 'lost; the sign byte of X2 - X1')
r([523, 524, 525], 'lost; DE = |X2 - X1| for DAD D at 530, HL kept at 1B3AH for MOV M,A at 526')
r([528], 'lost; the divisor of DIVI at 536 (read at 534) must be |X2 - X1|')
r([548], 'sign(dY) used as the slope\'s sign: erratum E5')
r([552, 554], 'lost; operand 2 = +Y1 (the pattern of 504-506)')
r([570], 'lost; XAC is the multiplier (thesis 4.4.4: YID for the actual X)')
r([575], 'sign of the product = sign of 1B43H, always +: erratum E5')
r([581, 582], 'only the magnitude is kept: erratum E6; at X2 the truncated slope stops short: erratum E7')
r([593], 'printed 78H ("t"): erratum E11, 04H ("i") in thesis-fixed')
r([600], 'as printed: a second RET (601 heads the next page), so 04H is never shown: erratum E11, CALL AUS in thesis-fixed')
r([608], 'the OCR printed this line twice')
r([640, 642, 644], '"000"/"001"/"002": letter O and digits (labels O00...)')
r([646, 663, 681, 699], 'labels O31/O41/O11/O21 printed with 0 for O')
r([651], 'O32 has 17 lines, not 18: no OUT raises the X pulse (erratum E9)')
r([654, 656], 'Y direction 1 in quadrant 3 (dY < 0): erratum E8')
r([746], 'lost; INPUT1 is called nowhere else and INPUT tests its result')
r([747, 748, 749, 750, 759, 760], 'dispatch as printed: erratum E10')
r(range(786, 796), 'ANA\'s test: erratum E12')
r([805, 819], 'SOEEN read as SOBE (no other label; B read as E)')
r([820, 823], 'ONYP never writes 0CH: erratum E13')
r([851], '1B39H (the sign of dY) where 1B38H (the delay) is meant: erratum E14')
r([866], 'H830 reversed = 038H, E read as 3: 0E8H. A is at least C8H here, so 38H would send every ratio to BBOL3')
r([888], 'END')
CONF = str.maketrans({'O':'0','I':'1','L':'1','B':'8','Z':'2','S':'5','K':'M','Н':'H','В':'B','А':'A','Α':'A','Λ':'A','Μ':'M','Х':'X','С':'C','G':'6'})
def norm(t):
    t = re.sub(r'\(.*?\)', '', t.upper())
    t = re.sub(r'[\s;:,.\'`•]', '', t)
    t = re.sub(r'^[A-Z0-9]+:', '', t)
    return t.translate(CONF)
rows = {}
for idx, line in enumerate(asm):
    m = re.search(r';\s*L(\d+)\b(.*)$', line)
    if not m: continue
    n = int(m.group(1)); extra = m.group(2).strip()
    code = line[:m.start()].rstrip()
    rows.setdefault(n, []).append((code, extra, idx))
# which lines are inside IF FIXED (fixed-only) branches: track IF/ELSE/ENDIF
state = []; fixed_only = set(); printed_branch = {}
for idx, line in enumerate(asm):
    s = line.strip().split(';')[0].split()
    if s[:2] == ['IF', 'FIXED']: state.append('F'); continue
    if s[:1] == ['ELSE'] and state: state[-1] = 'P'; continue
    if s[:1] == ['ENDIF'] and state: state.pop(); continue
    m = re.search(r';\s*L(\d+)\b', line)
    if m and state and state[-1] == 'F': fixed_only.add((int(m.group(1)), idx))
out = ['| line | OCR text | reconstructed (build thesis) | status | reason / note |', '|---|---|---|---|---|']
counts = {'printed': 0, 'corrected': 0, 'new': 0}
for n in range(1, 889):
    if 303 <= n <= 498:
        continue
    cands = [c for c in rows.get(n, []) if (n, c[2]) not in fixed_only]
    if not cands:
        stmt = '(none)'; extra = ''
    else:
        parts = []
        for code, ex, _ in cands:
            c = re.sub(r'\s+', ' ', code.strip())
            if c.startswith('; '): c = c[1:].strip()
            parts.append(c)
        stmt = ' '.join(parts); extra = ' '.join(ex for _, ex, _ in cands)
    oc = O.get(n, ocr.get(n, '—'))
    if not oc or oc == '-': oc = '—'
    if 'NEW' in extra: status = 'new'
    elif norm(oc.split(';')[-1]) == norm(stmt) or norm(oc) == norm(stmt): status = 'printed'
    else: status = 'corrected'
    counts[status] += 1
    why = REASON.get(n, '')
    if not why and status == 'corrected': why = 'OCR character confusions (0/O/D, 1/I/L, 8/B, mnemonic letters)'
    stmt = stmt.replace('|', '\\|'); oc = oc.replace('|', '\\|')
    out.append(f'| {n} | {oc} | `{stmt}` | {status} | {why} |')
    if n == 302:
        out.append('| 303–498 | (pages missing) | see "The lost pages" | new | 196 lines lost; reconstruction below |')
print('\n'.join(out))
print(f'\nCounts over the 692 lines present (1–302, 499–888): printed {counts["printed"]}, '
      f'corrected {counts["corrected"]}, new {counts["new"]}.', file=sys.stderr)
