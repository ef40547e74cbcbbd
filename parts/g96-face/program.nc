(G96 facing with a G50 S limit, a dwell, G97 keeping the rpm, G28 home)
G50 S2500;
T0101 M03;
G00 X104 Z0;
G96 S150;
G99 G01 X0 F0.2;
G04 P1500;
G97;
G01 W3 F0.5;
G28 U0 W0;
M05;
M30;
