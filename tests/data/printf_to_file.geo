/* A .geo that writes a file: Printf with a redirection is refused
   (Printf("no") > "in a comment" is not a command). */
Printf("to the terminal: allowed");
Printf("x = %g", 1) > "flowform_printf_wrote_this";
